// Tests of write_atomic and write_text: all or nothing, no temp file left behind.
#include "envcrust/io.h"
#include "io_test_support.h"

#include <unistd.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace envcrust::io {
namespace {

using testing::io_error_of;

class AtomicWrite : public testing::TempDirTest {};

std::string contents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST_F(AtomicWrite, writes_the_target_and_leaves_no_temp_file) {
  const auto file = path("report.json");
  write_text(file, "{\"ok\": true}\n");
  EXPECT_EQ(contents(file), "{\"ok\": true}\n");
  EXPECT_EQ(files(), std::vector<std::string>{"report.json"});
}

TEST_F(AtomicWrite, replaces_an_existing_target) {
  const auto file = write("report.txt", "old contents that are longer\n");
  write_text(file, "new\n");
  EXPECT_EQ(contents(file), "new\n");
  EXPECT_EQ(files(), std::vector<std::string>{"report.txt"});
}

TEST_F(AtomicWrite, keeps_old_target_and_removes_temp_file_when_fill_throws) {
  const auto file = write("mesh.off", "old\n");
  std::filesystem::path seen_temp;
  EXPECT_THROW(write_atomic(file, true,
                            [&](std::ostream& out) {
                              out << "half of a new file";
                              out.flush();
                              throw std::runtime_error("fill failed");
                            }),
               std::runtime_error);
  EXPECT_EQ(contents(file), "old\n");
  EXPECT_EQ(files(), std::vector<std::string>{"mesh.off"});
}

TEST_F(AtomicWrite, writes_nothing_when_fill_throws_and_no_target_existed) {
  const auto file = path("new.ply");
  EXPECT_THROW(write_atomic(file, true, [](std::ostream&) { throw IoError("inner"); }), IoError);
  EXPECT_TRUE(files().empty());
}

TEST_F(AtomicWrite, temp_file_is_hidden_next_to_the_target) {
  const auto file = path("mesh.ply");
  std::vector<std::string> during;
  write_atomic(file, true, [&](std::ostream& out) {
    out << "x";
    during = files();
  });
  ASSERT_EQ(during.size(), 1U);
  EXPECT_EQ(during[0].rfind(".mesh.ply.", 0), 0U) << during[0];
  EXPECT_EQ(during[0].substr(during[0].size() - 4), ".tmp");
  EXPECT_EQ(files(), std::vector<std::string>{"mesh.ply"});
}

TEST_F(AtomicWrite, reports_failed_stream_and_keeps_old_target) {
  const auto file = write("a.txt", "old\n");
  EXPECT_EQ(io_error_of([&] {
              write_atomic(file, false, [](std::ostream& out) { out.setstate(std::ios::badbit); });
            }),
            file.string() + ": write failed (disk full?)");
  EXPECT_EQ(contents(file), "old\n");
  EXPECT_EQ(files(), std::vector<std::string>{"a.txt"});
}

TEST_F(AtomicWrite, reports_target_that_is_a_folder) {
  std::filesystem::create_directory(path("out.txt"));
  std::filesystem::create_directory(path("out.txt") / "inside");
  const auto file = path("out.txt");
  const std::string message = io_error_of([&] { write_text(file, "x"); });
  EXPECT_EQ(message.rfind(file.string() + ": cannot replace file (", 0), 0U) << message;
  EXPECT_EQ(files(), std::vector<std::string>{"out.txt"});
}

TEST_F(AtomicWrite, follows_a_symbolic_link_and_keeps_it) {
  const auto target = write("real.txt", "old\n");
  std::filesystem::create_symlink(target, path("link.txt"));
  write_text(path("link.txt"), "new\n");
  EXPECT_TRUE(std::filesystem::is_symlink(path("link.txt")));
  EXPECT_EQ(contents(target), "new\n");
  EXPECT_EQ(files(), (std::vector<std::string>{"link.txt", "real.txt"}));
}

TEST_F(AtomicWrite, refuses_to_replace_a_device) {
  // Renaming a temp file onto /dev/null would replace the device node (as root).
  const std::filesystem::path null = "/dev/null";
  if (!std::filesystem::is_character_file(null)) GTEST_SKIP() << "no /dev/null";
  const std::string expected = "/dev/null: exists and is not a regular file (a device, pipe or socket): not replaced";
  EXPECT_EQ(io_error_of([&] { write_text(null, "x"); }), expected);
  EXPECT_EQ(io_error_of([&] { check_output_path(null, OutputKind::Text); }), expected);
  EXPECT_TRUE(std::filesystem::is_character_file(null));
}

TEST_F(AtomicWrite, a_signal_handler_can_remove_the_file_being_filled) {
  const auto file = path("mesh.ply");
  EXPECT_THROW(write_atomic(file, true,
                            [&](std::ostream& out) {
                              out << "half";
                              EXPECT_EQ(files().size(), 1u);  // the hidden temp file
                              remove_pending_temp_files();
                              EXPECT_TRUE(files().empty());
                            }),
               IoError);  // its rename then fails
  EXPECT_TRUE(files().empty());
  remove_pending_temp_files();  // nothing pending: a no-op
}

TEST_F(AtomicWrite, an_unwritable_folder_is_found_before_the_run) {
  std::filesystem::create_directory(path("locked"));
  std::filesystem::permissions(path("locked"), std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  const auto file = path("locked") / "r.json";
  if (::access(path("locked").c_str(), W_OK) == 0) {
    std::filesystem::permissions(path("locked"), std::filesystem::perms::owner_all);
    GTEST_SKIP() << "running as root: every folder is writable";
  }
  EXPECT_EQ(io_error_of([&] { check_output_path(file, OutputKind::Text); }),
            file.string() + ": folder '" + path("locked").string() + "' is not writable (Permission denied)");
  std::filesystem::permissions(path("locked"), std::filesystem::perms::owner_all);
}

TEST_F(AtomicWrite, output_paths_are_checked_before_anything_is_written) {
  EXPECT_NO_THROW(check_output_path(path("m.PLY"), OutputKind::Mesh));
  EXPECT_NO_THROW(check_output_path(path("p.xyz"), OutputKind::Points));
  EXPECT_NO_THROW(check_output_path(path("r.json"), OutputKind::Text));
  EXPECT_NO_THROW(check_output_path("relative.png", OutputKind::Image));  // the current folder
  const auto mesh = path("m.xyz");
  EXPECT_EQ(io_error_of([&] { check_output_path(mesh, OutputKind::Mesh); }),
            mesh.string() + ": unknown extension '.xyz' (expected .ply, .off, .obj, .stl)");
  const auto points = path("p.off");
  EXPECT_EQ(io_error_of([&] { check_output_path(points, OutputKind::Points); }),
            points.string() + ": unknown extension '.off' (expected .xyz, .ply)");
  const auto image = path("i");
  EXPECT_EQ(io_error_of([&] { check_output_path(image, OutputKind::Image); }),
            image.string() + ": no extension (expected .png)");
  const auto missing = path("no_such_folder") / "r.json";
  EXPECT_EQ(io_error_of([&] { check_output_path(missing, OutputKind::Text); }),
            missing.string() + ": folder '" + path("no_such_folder").string() + "' does not exist");
  EXPECT_FALSE(std::filesystem::exists(path("no_such_folder")));
}

}  // namespace
}  // namespace envcrust::io

