// libFuzzer target: the quantity parser must either return a finite SI value or throw
// InputError — never crash, hang, return NaN/inf, or throw anything else.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "physics/units.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  // First byte picks the dimension so one corpus covers every unit table.
  const auto dim = static_cast<sweetspot::Dimension>(data[0] % 11);
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    const double v = sweetspot::parse_quantity(text, dim);
    if (!std::isfinite(v)) std::abort();
  } catch (const sweetspot::InputError&) {
  }
  try {
    for (double v : sweetspot::parse_quantity_list(text, dim)) {
      if (!std::isfinite(v)) std::abort();
    }
  } catch (const sweetspot::InputError&) {
  }
  return 0;
}
