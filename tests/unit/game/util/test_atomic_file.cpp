// Atomic writes: complete contents or the old file, never a partial one; errors name the path.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

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
