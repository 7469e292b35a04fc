// Atomic writes: complete contents or the old file, never a partial one; errors name the path.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/stat.h>

#include "game/util/atomic_file.hpp"
#include "physics/error.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;

namespace {
std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
}  // namespace

TEST_CASE("write_file_atomic replaces a file and leaves no temporary behind", "[util]") {
  const auto dir = std::filesystem::temp_directory_path() / "sweetspot_atomic_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto file = dir / "out.csv";
  write_file_atomic(file, "first\n");
  CHECK(slurp(file) == "first\n");
  const std::string big(1 << 20, 'x');
  write_file_atomic(file, big);
  CHECK(slurp(file) == big);
  int count = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++count;
  CHECK(count == 1);
  CHECK((std::filesystem::status(file).permissions() & std::filesystem::perms::others_read) !=
        std::filesystem::perms::none);
  std::filesystem::remove_all(dir);
}

TEST_CASE("write_file_atomic names the path when it cannot write", "[util][bad-input]") {
  CHECK_THROWS_WITH(write_file_atomic("/nonexistent-dir/sub/out.csv", "x"),
                    Contains("/nonexistent-dir/sub/out.csv"));
  CHECK_THROWS_AS(write_file_atomic(std::filesystem::temp_directory_path(), "x"), InputError);
}

TEST_CASE("write_file_atomic writes through a symlink and keeps the file's mode", "[util][hostile]") {
  namespace fs = std::filesystem;
  const auto dir = fs::temp_directory_path() / "sweetspot_atomic_link";
  fs::remove_all(dir);
  fs::create_directories(dir / "sub");
  const auto real = dir / "sub" / "real.csv";
  write_file_atomic(real, "old\n");
  fs::permissions(real, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  fs::create_symlink("sub/real.csv", dir / "link.csv");  // relative, resolved from the link's folder
  write_file_atomic(dir / "link.csv", "new\n");
  CHECK(fs::is_symlink(dir / "link.csv"));
  CHECK(slurp(real) == "new\n");
  CHECK(fs::status(real).permissions() == (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
  // A dangling link creates the file it names.
  fs::create_symlink("made.csv", dir / "dangling.csv");
  write_file_atomic(dir / "dangling.csv", "x");
  CHECK(fs::is_symlink(dir / "dangling.csv"));
  CHECK(slurp(dir / "made.csv") == "x");
  // A loop of links is refused, not followed forever.
  fs::create_symlink("loop_b", dir / "loop_a");
  fs::create_symlink("loop_a", dir / "loop_b");
  CHECK_THROWS_WITH(write_file_atomic(dir / "loop_a", "x"), Contains("symbolic links"));
  fs::remove_all(dir);
}

TEST_CASE("write_file_atomic writes devices in place and refuses FIFOs", "[util][hostile]") {
  namespace fs = std::filesystem;
  write_file_atomic("/dev/null", "discarded");
  CHECK(fs::is_character_file("/dev/null"));  // still the device, not a regular file
  if (fs::exists("/dev/full")) CHECK_THROWS_WITH(write_file_atomic("/dev/full", "x"), Contains("/dev/full"));
  const auto dir = fs::temp_directory_path() / "sweetspot_atomic_fifo";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto fifo = dir / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK_THROWS_WITH(write_file_atomic(fifo, "x"), Contains("not a regular file"));  // and no hang
  CHECK(fs::is_fifo(fifo));
  fs::remove_all(dir);
}

TEST_CASE("an output that is the input is refused", "[util][hostile]") {
  namespace fs = std::filesystem;
  const auto dir = fs::temp_directory_path() / "sweetspot_atomic_same";
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_file_atomic(dir / "s.toml", "a = 1\n");
  fs::create_hard_link(dir / "s.toml", dir / "hard.toml");
  CHECK_THROWS_WITH(refuse_output_over_input(dir / "s.toml", dir / "s.toml", "--csv"), Contains("--csv"));
  CHECK_THROWS_AS(refuse_output_over_input(dir / "hard.toml", dir / "s.toml", "-o"), InputError);
  CHECK_NOTHROW(refuse_output_over_input(dir / "new.csv", dir / "s.toml", "--csv"));
  fs::remove_all(dir);
}
