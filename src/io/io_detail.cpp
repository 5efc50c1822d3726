// Shared io helpers: one-line error messages, whole-file reading, tokenizing and exact number text.
#include "io_detail.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <ostream>
#include <string>
#include <system_error>

namespace envcrust::io::detail {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

}  // namespace

void fail(const std::filesystem::path& path, const std::string& problem) {
  throw IoError(path.string() + ": " + problem);
}

void fail_at(const std::filesystem::path& path, std::size_t line, const std::string& problem) {
  throw IoError(path.string() + ":" + std::to_string(line) + ": " + problem);
}

void unknown_extension(const std::filesystem::path& path, const char* expected) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory, not a file");  // not "no extension"
  const std::string extension = path.extension().string();
  fail(path, (extension.empty() ? std::string("no extension")
                                : "unknown extension '" + extension + "'") +
                 " (expected " + expected + ")");
}

std::string read_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    fail(path, "is a directory, not a file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    fail(path, "cannot open file");
  }
  std::string data;
  std::array<char, 1 << 16> buffer{};
  while (in.read(buffer.data(), buffer.size()) || in.gcount() > 0) {
    data.append(buffer.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) {
    fail(path, "read error");
  }
  return data;
}

bool parse_double(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token.front() == '-') {
      return false;
    }
  }
  if (token.empty()) {
    return false;
  }
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (end != token.data() + token.size()) return false;
  if (ec == std::errc::result_out_of_range) {
    // A number beyond double's range ("1e999") reads as +-inf (the readers then say
    // "non-finite"), one below it as its nearest double (0 or a subnormal), as strtod gives.
    value = std::strtod(std::string(token).c_str(), nullptr);
    return true;
  }
  return ec == std::errc();
}

bool parse_int(std::string_view token, std::int64_t& value) {
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token.front() == '-') {
      return false;
    }
  }
  if (token.empty()) {
    return false;
  }
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  // An integer beyond 64 bits is no integer the readers can use: refused, not wrapped.
  return end == token.data() + token.size() && ec == std::errc();
}

void split_tokens(std::string_view line, std::vector<std::string_view>& tokens) {
  tokens.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) {
      ++i;
    }
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i])) {
      ++i;
    }
    if (i > start) {
      tokens.push_back(line.substr(start, i - start));
    }
  }
}

void split_fields(std::string_view line, std::vector<std::string_view>& tokens) {
  if (line.find(',') == std::string_view::npos) return split_tokens(line, tokens);
  // Each comma ends a field, so an empty one ("1,,2") stays a token and fails as no number.
  tokens.clear();
  std::size_t start = 0;
  while (true) {
    const std::size_t end = std::min(line.find(',', start), line.size());
    std::string_view field = line.substr(start, end - start);
    while (!field.empty() && is_space(field.front())) field.remove_prefix(1);
    while (!field.empty() && is_space(field.back())) field.remove_suffix(1);
    tokens.push_back(field);
    if (end == line.size()) break;
    start = end + 1;
  }
}

std::string_view strip_comment(std::string_view line) {
  const auto hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

void append_double(std::string& out, double value) {
  std::array<char, 32> buffer{};
  const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  out.append(buffer.data(), ec == std::errc() ? end : buffer.data());
}

void append_point(std::string& out, const Point3& p) {
  append_double(out, p.x());
  out += ' ';
  append_double(out, p.y());
  out += ' ';
  append_double(out, p.z());
}

void flush_buffer(std::ostream& out, std::string& buffer, bool force) {
  constexpr std::size_t threshold = 1 << 16;
  if (force || buffer.size() >= threshold) {
    out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    buffer.clear();
  }
}

std::string quote(std::string_view token) {
  constexpr std::size_t max_shown = 40;
  std::string shown(token.substr(0, max_shown));
  for (char& c : shown) {
    // Binary garbage must not break the one-line message.
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) {
      c = '?';
    }
  }
  if (token.size() > max_shown) {
    shown += "...";
  }
  return "'" + shown + "'";
}

void check_finite(const std::filesystem::path& path, const std::vector<Point3>& points,
                  const char* what) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point3& p = points[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) {
      fail(path, std::string("cannot write non-finite coordinate (") + what + " " +
                     std::to_string(i) + ")");
    }
  }
}

bool LineCursor::next(std::string_view& line) {
  if (pos_ >= text_.size()) {
    return false;
  }
  const auto newline = text_.find('\n', pos_);
  const std::size_t end = newline == std::string_view::npos ? text_.size() : newline;
  line = text_.substr(pos_, end - pos_);
  if (!line.empty() && line.back() == '\r') {
    line.remove_suffix(1);
  }
  pos_ = newline == std::string_view::npos ? text_.size() : newline + 1;
  ++next_line_;
  return true;
}

bool TokenCursor::next(std::string_view& token) {
  while (pos_ < text_.size() && is_space(text_[pos_])) {
    if (text_[pos_] == '\n') {
      ++line_;
    }
    ++pos_;
  }
  token_line_ = line_;
  if (pos_ >= text_.size()) {
    return false;
  }
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_])) {
    ++pos_;
  }
  token = text_.substr(start, pos_ - start);
  return true;
}

}  // namespace envcrust::io::detail
