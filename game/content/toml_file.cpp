#include "game/content/toml_file.hpp"

#include <charconv>
#include <fstream>
#include <sstream>
#include <system_error>

#include "game/content/quantity_text.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace fs = std::filesystem;

std::uintmax_t check_data_file(const fs::path& path, std::string_view what, std::uintmax_t max_bytes) {
  const std::string name = path.string();
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) {
    throw InputError(name + ": " + std::string(what) + " file not found" + (ec ? " (" + ec.message() + ")" : ""));
  }
  if (fs::is_directory(st)) throw InputError(name + ": " + std::string(what) + " is a directory, not a file");
  // A FIFO would block and a device (/dev/zero) never end: only regular files are read.
  if (!fs::is_regular_file(st)) throw InputError(name + ": " + std::string(what) + " is not a regular file");
  const std::uintmax_t bytes = fs::file_size(path, ec);
  if (ec) throw InputError(name + ": cannot read the " + std::string(what) + "'s size (" + ec.message() + ")");
  if (bytes > max_bytes) {
    throw InputError(name + ": " + std::string(what) + " is " + std::to_string(bytes) + " bytes, over the limit of " +
                     std::to_string(max_bytes) + " bytes");
  }
  note_input_file(path);  // no output of this process may replace it
  return bytes;
}

std::string read_data_file(const fs::path& path, std::string_view what, std::uintmax_t max_bytes) {
  const std::string name = path.string();
  const std::uintmax_t bytes = check_data_file(path, what, max_bytes);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(name + ": cannot open the " + std::string(what) + " (permission denied or unreadable)");
  std::string text(static_cast<std::size_t>(bytes), '\0');
  in.read(text.data(), static_cast<std::streamsize>(bytes));
  if (in.gcount() != static_cast<std::streamsize>(bytes)) {
    throw InputError(name + ": reading the " + std::string(what) + " failed (file changed or unreadable)");
  }
  return text;
}

const char* toml_type_name(toml::node_type t) {
  switch (t) {
    case toml::node_type::table: return "table";
    case toml::node_type::array: return "array";
    case toml::node_type::string: return "string";
    case toml::node_type::integer: return "integer";
    case toml::node_type::floating_point: return "float";
    case toml::node_type::boolean: return "boolean";
    case toml::node_type::date: return "date";
    case toml::node_type::time: return "time";
    case toml::node_type::date_time: return "date-time";
    default: return "value";
  }
}

bool toml_scalar_text(const toml::node& n, std::string& out) {
  if (auto s = n.value_exact<std::string>()) {
    out = *s;
    return true;
  }
  if (auto i = n.value_exact<std::int64_t>()) {
    out = std::to_string(*i);
    return true;
  }
  if (auto d = n.value_exact<double>()) {
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof buf, *d);  // shortest round-trip form
    out.assign(buf, res.ptr);
    return true;
  }
  if (auto b = n.value_exact<bool>()) {
    out = *b ? "true" : "false";
    return true;
  }
  return false;
}

TomlFile TomlFile::parse(std::string_view text, std::string source) {
  try {
    toml::table root = toml::parse(text, source);
    return TomlFile(std::move(root), std::move(source));
  } catch (const toml::parse_error& e) {
    throw InputError(source + ":" + std::to_string(e.source().begin.line) + ":" +
                     std::to_string(e.source().begin.column) + ": malformed TOML: " + std::string(e.description()));
  }
}

TomlFile TomlFile::read(const fs::path& path, std::string_view what) {
  return parse(read_data_file(path, what), path.string());
}

std::string TomlFile::where(const toml::node& n) const {
  return source_ + ":" + std::to_string(n.source().begin.line);
}

void TomlFile::fail(const toml::node& n, std::string_view key, std::string_view message) const {
  throw InputError(where(n) + ": " + std::string(key) + ": " + std::string(message));
}

std::string TomlFile::in_context(const std::string& message, const std::string& context) const {
  // A message that already names its context ("club 'driver'.inertia: ...") gets it once.
  const auto with = [&](const std::string& where, const std::string& rest) {
    return rest.rfind(context, 0) == 0 ? where + rest : where + context + ": " + rest;
  };
  if (message.rfind(source_ + ":", 0) == 0) {
    const auto colon = message.find(": ", source_.size() + 1);
    if (colon != std::string::npos) return with(message.substr(0, colon + 2), message.substr(colon + 2));
  }
  return with(source_ + ": ", message);
}

void TomlFile::only_keys(const toml::table& t, std::string_view what,
                         std::initializer_list<std::string_view> allowed) const {
  for (const auto& [k, v] : t) {
    bool ok = false;
    for (const auto a : allowed) ok = ok || k.str() == a;
    if (ok) continue;
    std::string names;
    for (const auto a : allowed) names += (names.empty() ? "" : ", ") + std::string(a);
    fail(v, std::string(what).empty() ? std::string(k.str()) : std::string(what) + "." + std::string(k.str()),
         "unknown key (allowed: " + names + ")");
  }
}

const toml::node& TomlFile::required(const toml::table& t, std::string_view key, std::string_view what) const {
  const toml::node* n = t.get(key);
  if (n == nullptr) fail(t, key, "missing (" + std::string(what) + ")");
  return *n;
}

const toml::table& TomlFile::table(const toml::node& n, std::string_view key) const {
  const toml::table* t = n.as_table();
  if (t == nullptr) fail(n, key, std::string("expected a table, got ") + toml_type_name(n.type()));
  return *t;
}

double TomlFile::quantity(const toml::node& n, std::string_view key, Dimension dim, const Range* range) const {
  std::string text;
  if (!(n.is_string() || n.is_number()) || !toml_scalar_text(n, text)) {
    fail(n, key, std::string("expected ") + (needs_unit(dim) ? "a quantity with its unit, e.g. \"10mm\"" : "a number") +
                     ", got " + toml_type_name(n.type()));
  }
  double v = 0.0;
  try {
    v = read_quantity(text, dim);
  } catch (const InputError& e) {
    fail(n, key, e.what());
  }
  // Said in the unit it was written in ("140%", "400mph"), with SI beside it.
  if (range != nullptr)
    if (const std::string why = written_range_refusal(key, text, v, dim, *range); !why.empty())
      throw InputError(where(n) + ": " + why);
  return v;
}

int TomlFile::whole_number(const toml::node& n, std::string_view key, const Range& range) const {
  const auto v = n.value_exact<std::int64_t>();
  if (!v) fail(n, key, std::string("expected a whole number such as 3, got ") + toml_type_name(n.type()));
  const double x = static_cast<double>(*v);
  if (const std::string why = range_refusal(key, x, range, ""); !why.empty()) throw InputError(where(n) + ": " + why);
  return static_cast<int>(*v);
}

double TomlFile::quantity_or(const toml::table& t, std::string_view key, Dimension dim, double fallback,
                             const Range* range) const {
  const toml::node* n = t.get(key);
  return n != nullptr ? quantity(*n, key, dim, range) : fallback;
}

std::vector<double> TomlFile::quantities(const toml::node& n, std::string_view key, Dimension dim, std::size_t count,
                                         const Range* range) const {
  const toml::array* a = n.as_array();
  if (a == nullptr || a->empty() || (count != 0 && a->size() != count)) {
    fail(n, key, "expected an array of " + (count ? std::to_string(count) : std::string("one or more")) +
                     " quantities" + (a ? ", got " + std::to_string(a->size()) : std::string()));
  }
  std::vector<double> out;
  for (const auto& e : *a) out.push_back(quantity(e, key, dim, range));
  return out;
}

std::vector<std::pair<double, double>> TomlFile::pairs(const toml::node& n, std::string_view key, Dimension dx,
                                                       Dimension dy) const {
  const toml::array* a = n.as_array();
  if (a == nullptr || a->empty()) fail(n, key, "expected an array of [x, y] pairs");
  std::vector<std::pair<double, double>> out;
  for (const auto& e : *a) {
    const toml::array* p = e.as_array();
    if (p == nullptr || p->size() != 2) fail(e, key, "each entry must be a pair [x, y]");
    out.emplace_back(quantity((*p)[0], key, dx), quantity((*p)[1], key, dy));
  }
  return out;
}

std::string TomlFile::text(const toml::node& n, std::string_view key) const {
  const auto s = n.value_exact<std::string>();
  if (!s) fail(n, key, std::string("expected a string, got ") + toml_type_name(n.type()));
  if (s->empty()) fail(n, key, "empty string (a value is needed)");
  return *s;
}

std::string TomlFile::text_or(const toml::table& t, std::string_view key, std::string fallback) const {
  const toml::node* n = t.get(key);
  return n != nullptr ? text(*n, key) : std::move(fallback);
}

bool TomlFile::boolean(const toml::node& n, std::string_view key) const {
  const auto b = n.value_exact<bool>();
  if (!b) fail(n, key, std::string("expected true or false, got ") + toml_type_name(n.type()));
  return *b;
}

std::vector<const toml::table*> TomlFile::tables(const toml::table& t, std::string_view key, bool required) const {
  std::vector<const toml::table*> out;
  const toml::node* n = t.get(key);
  if (n == nullptr) {
    if (required) throw InputError(source_ + ": needs at least one [[" + std::string(key) + "]] table");
    return out;
  }
  const toml::array* a = n->as_array();
  if (a == nullptr) fail(*n, key, "expected [[" + std::string(key) + "]] tables");
  for (const auto& e : *a) {
    if (!e.is_table()) fail(e, key, "expected [[" + std::string(key) + "]] tables");
    out.push_back(e.as_table());
  }
  if (required && out.empty()) throw InputError(source_ + ": needs at least one [[" + std::string(key) + "]] table");
  return out;
}

}  // namespace sweetspot
