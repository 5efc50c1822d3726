// Base64 encoding of binary blocks (RFC 4648, with padding), streamed: the HTML report embeds
// its typed arrays this way, tens of megabytes for a mesh of a million vertices.
#pragma once

#include <cstddef>
#include <iosfwd>

namespace envcrust::cli::html {

/// Writes the `size` bytes at `data` to `out` as base64, without line breaks.
void write_base64(std::ostream& out, const void* data, std::size_t size);

/// The length of the base64 text of `size` bytes: 4 characters per 3 bytes, padded.
constexpr std::size_t base64_length(std::size_t size) { return (size + 2) / 3 * 4; }

}  // namespace envcrust::cli::html
