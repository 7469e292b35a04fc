#include "game/content/course_file.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "game/content/toml_file.hpp"
#include "game/content/world_asset.hpp"
#include "physics/atmosphere.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

// The ground point under [x, z] on the world, or InputError naming where it came from; its
// surface must be one of `allowed` (a cup on the green, a tee on dry ground).
Vec3 ground_at(const WorldAsset& w, double x, double z, const std::string& where, const std::string& what,
               std::initializer_list<SurfaceKind> allowed) {
  const WorldDescription& d = w.description();
  SurfaceContact hit;
  const std::string spot = what + " [" + std::to_string(x) + " m, " + std::to_string(z) + " m]";
  if (!ground_under(*w.world, x, z, d.bounds_max.y(), d.bounds_max.y() - d.bounds_min.y(), &hit))
    throw InputError(where + ": " + spot + " is off the ground of world '" + w.name + "' (" + ground_extent_text(d) + ")");
  const SurfaceKind kind = w.world->material(hit.material).kind;
  if (std::find(allowed.begin(), allowed.end(), kind) == allowed.end()) {
    std::string names;
    for (const SurfaceKind k : allowed) names += std::string(names.empty() ? "" : ", ") + to_string(k);
    throw InputError(where + ": " + spot + " lies on " + to_string(kind) + " (allowed: " + names + ")");
  }
  return Vec3(x, hit.point.y(), z);
}

// `key`'s array of [x, z] points, at most `max` of them.
const toml::array& point_list(const TomlFile& f, const toml::node& n, const std::string& key, std::size_t max) {
  const toml::array* arr = n.as_array();
  if (arr == nullptr || arr->size() > max)
    f.fail(n, key, "expected [[x, z], ...] with at most " + std::to_string(max) + " points");
  return *arr;
}

// Every hole's stroke index given, each of 1..n once; or none given, and then by length (the
// longest hole index 1), the usual proxy for difficulty when a club has not rated its holes.
void assign_stroke_index(const TomlFile& f, Course& c, const std::vector<const toml::node*>& given) {
  const std::size_t n = c.holes.size();
  if (given.empty()) {
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return c.holes[a].length() > c.holes[b].length(); });
    for (std::size_t k = 0; k < n; ++k) c.holes[order[k]].stroke_index = static_cast<int>(k + 1);
    return;
  }
  if (given.size() != n) f.fail(*given.front(), "index", "give every hole an index, or none (then by length)");
  std::vector<bool> seen(n + 1, false);
  for (std::size_t i = 0; i < n; ++i) {
    const int si = c.holes[i].stroke_index;
    if (si < 1 || static_cast<std::size_t>(si) > n || seen[static_cast<std::size_t>(si)])
      f.fail(*given[i], "index", "stroke indexes must be 1.." + std::to_string(n) + ", each once");
    seen[static_cast<std::size_t>(si)] = true;
  }
}

}  // namespace

double CourseHole::length() const {
  double s = 0.0;
  Vec3 from = tee;
  for (const Vec3& b : bends) {
    s += std::hypot(b.x() - from.x(), b.z() - from.z());
    from = b;
  }
  return s + std::hypot(pin.x() - from.x(), pin.z() - from.z());
}

int Course::par() const {
  int p = 0;
  for (const CourseHole& h : holes) p += h.par;
  return p;
}

Course load_course(const Assets& assets, std::string_view name_or_path) {
  // A path (a '/' or a .toml name) is read as given; anything else is a built-in name.
  std::filesystem::path path(name_or_path);
  std::error_code dir_ec;
  if (std::filesystem::is_directory(path, dir_ec)) {
    path /= "course.toml";  // a course directory (course import writes one)
  } else if (name_or_path.find('/') == std::string_view::npos && path.extension() != ".toml") {
    // A built-in course: courses/NAME.toml, or an imported one, courses/NAME/course.toml.
    path = assets.root() / "courses" / (std::string(name_or_path) + ".toml");
    if (std::error_code ec; !std::filesystem::exists(path, ec))
      path = assets.root() / "courses" / std::string(name_or_path) / "course.toml";
    if (std::error_code ec; !std::filesystem::exists(path, ec)) {
      std::string names;
      for (const auto& n : course_names(assets)) names += (names.empty() ? "" : ", ") + n;
      throw InputError("unknown course '" + std::string(name_or_path) + "' (allowed: " + names + ", or a path to a .toml)");
    }
  }
  const TomlFile f = TomlFile::read(path, "course");
  f.only_keys(f.root(), "", {"name", "hole"});
  Course c;
  c.source = path;
  c.name = f.text(f.required(f.root(), "name", "the course's name"), "name");
  int last = 0;
  std::vector<const toml::node*> index_nodes;
  for (const toml::table* t : f.tables(f.root(), "hole", true)) {
    f.only_keys(*t, "hole", {"number", "par", "world", "tee", "pin", "bends", "pins", "tees", "index", "wind_speed",
                             "wind_toward"});
    CourseHole h;
    static constexpr Range kNumber{1.0, 18.0};
    h.number = f.whole_number(f.required(*t, "number", "the hole's number, 1-18"), "number", kNumber);
    if (h.number != last + 1) f.fail(*t->get("number"), "number", "holes must be numbered 1, 2, 3, ... in order");
    last = h.number;
    h.par = f.whole_number(f.required(*t, "par", "3 to 6"), "par", CourseHole::kPar);
    const toml::node& wn = f.required(*t, "world", "a world of assets/worlds");
    h.world_name = f.text(wn, "world");
    // A world given as a relative path is found beside the course file, wherever it is run.
    if (is_world_path(h.world_name) && std::filesystem::path(h.world_name).is_relative())
      h.world_name = (path.parent_path() / h.world_name).string();
    try {
      h.world = assets.world(h.world_name);
    } catch (const InputError& e) {
      throw InputError(f.where(wn) + ": world: " + e.what());
    }
    if (h.world == nullptr || h.world->sport != "golf")
      f.fail(wn, "world", "'" + h.world_name + "' is not a golf world (a hole needs a course world with a green)");
    const toml::node& tn = f.required(*t, "tee", "the tee spot [x, z] on the world");
    const auto tee = f.quantities(tn, "tee", Dimension::Length, 2);
    h.tee = ground_at(*h.world, tee[0], tee[1], f.where(tn), "tee",
                      {SurfaceKind::Tee, SurfaceKind::Fairway, SurfaceKind::Rough, SurfaceKind::Grass});
    if (const toml::node* pn = t->get("pin")) {
      const auto pin = f.quantities(*pn, "pin", Dimension::Length, 2);
      h.pin = ground_at(*h.world, pin[0], pin[1], f.where(*pn), "pin", {SurfaceKind::Green});
    } else if (h.world->pin) {
      h.pin = *h.world->pin;
    } else {
      throw InputError(f.where(*t) + ": hole " + std::to_string(h.number) + ": missing pin (world '" + h.world_name +
                       "' has no cup: give pin = [x, z])");
    }
    if (const toml::node* pn = t->get("pins")) {
      for (const toml::node& p : point_list(f, *pn, "pins", CourseHole::kMaxPins)) {
        const auto xz = f.quantities(p, "pins", Dimension::Length, 2);
        h.more_pins.push_back(ground_at(*h.world, xz[0], xz[1], f.where(p), "pin", {SurfaceKind::Green}));
      }
    }
    for (const toml::table* ts : f.tables(*t, "tees", false)) {
      if (h.tee_sets.size() >= CourseHole::kMaxTeeSets)
        f.fail(*ts, "tees", "more than " + std::to_string(CourseHole::kMaxTeeSets) + " tee sets on one hole");
      f.only_keys(*ts, "tees", {"name", "at"});
      CourseHole::TeeSet set;
      set.name = f.text(f.required(*ts, "name", "the tee set's name (\"white\")"), "name");
      const toml::node& an = f.required(*ts, "at", "the tee spot [x, z] on the world");
      const auto xz = f.quantities(an, "at", Dimension::Length, 2);
      set.at = ground_at(*h.world, xz[0], xz[1], f.where(an), "tee",
                         {SurfaceKind::Tee, SurfaceKind::Fairway, SurfaceKind::Rough, SurfaceKind::Grass});
      for (const CourseHole::TeeSet& other : h.tee_sets)
        if (other.name == set.name) f.fail(*ts, "name", "tee set '" + set.name + "' is given twice for this hole");
      h.tee_sets.push_back(set);
    }
    if (const toml::node* bn = t->get("bends")) {
      const WorldDescription& d = h.world->description();
      for (const toml::node& p : point_list(f, *bn, "bends", CourseHole::kMaxBends)) {
        const auto xz = f.quantities(p, "bends", Dimension::Length, 2);
        if (xz[0] < d.bounds_min.x() || xz[0] > d.bounds_max.x() || xz[1] < d.bounds_min.z() || xz[1] > d.bounds_max.z())
          f.fail(p, "bends", "point [" + std::to_string(xz[0]) + " m, " + std::to_string(xz[1]) + " m] is off the world (" +
                                 ground_extent_text(d) + ")");
        SurfaceContact hit;  // over water or sand too: the line is an aim, not a lie
        const double y = ground_under(*h.world->world, xz[0], xz[1], d.bounds_max.y(), d.bounds_max.y() - d.bounds_min.y(), &hit)
                             ? hit.point.y() : 0.0;
        h.bends.emplace_back(xz[0], y, xz[1]);
      }
    }
    if (const toml::node* in = t->get("index")) {
      static constexpr Range kIndex{1.0, 18.0};
      h.stroke_index = f.whole_number(*in, "index", kIndex);
      index_nodes.push_back(in);
    }
    if (const toml::node* wn2 = t->get("wind_speed")) {
      h.wind_speed = f.quantity(*wn2, "wind_speed", Dimension::Speed, &Environment::kWindSpeed);
      h.wind_toward = f.quantity_or(*t, "wind_toward", Dimension::Angle, 0.0, &Environment::kWindDirection);
    } else if (const toml::node* wt = t->get("wind_toward")) {
      f.fail(*wt, "wind_toward", "a wind direction needs wind_speed too");
    }
    c.holes.push_back(h);
  }
  assign_stroke_index(f, c, index_nodes);
  return c;
}

std::vector<std::string> tee_set_names(const Course& course) {
  std::vector<std::string> out;
  for (const CourseHole& h : course.holes)
    for (const CourseHole::TeeSet& t : h.tee_sets)
      if (std::find(out.begin(), out.end(), t.name) == out.end()) out.push_back(t.name);
  return out;
}

void set_up(Course& course, const CourseSetup& setup, const char* tees_key, const char* pins_key) {
  check_range(pins_key, setup.pin_set, CourseSetup::kPinSet, "");
  if (!setup.tees.empty()) {
    const std::vector<std::string> names = tee_set_names(course);
    if (std::find(names.begin(), names.end(), setup.tees) == names.end()) {
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      throw InputError(std::string(tees_key) + ": course '" + course.name + "' has no tee set '" + setup.tees + "' (allowed: " +
                       (list.empty() ? std::string("none: its holes have one tee each") : list) + ")");
    }
  }
  // A set past the course's last is refused, not wrapped round to an earlier one; a hole with
  // fewer sets than the course's most takes its own in turn.
  std::size_t sets = 1;
  for (const CourseHole& h : course.holes) sets = std::max(sets, h.more_pins.size() + 1);
  if (setup.pin_set > 0 && static_cast<std::size_t>(setup.pin_set) > sets)
    throw InputError(std::string(pins_key) + " " + std::to_string(setup.pin_set) + ": course '" + course.name + "' has " +
                     std::to_string(sets) + (sets == 1 ? " pin set" : " pin sets") + " (allowed 0.." + std::to_string(sets) +
                     "; 0 mixes them)");
  for (std::size_t i = 0; i < course.holes.size(); ++i) {
    CourseHole& h = course.holes[i];
    for (const CourseHole::TeeSet& t : h.tee_sets)
      if (t.name == setup.tees) h.tee = t.at;
    const std::size_t set = setup.pin_set == 0 ? i : static_cast<std::size_t>(setup.pin_set - 1);
    const std::size_t k = set % (h.more_pins.size() + 1);
    if (k > 0) h.pin = h.more_pins[k - 1];
  }
  course.setup = setup;
}

std::vector<std::string> course_names(const Assets& assets) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(assets.root() / "courses", ec)) {
    std::error_code e2;
    if (e.path().extension() == ".toml") out.push_back(e.path().stem().string());
    else if (std::filesystem::is_regular_file(e.path() / "course.toml", e2)) out.push_back(e.path().filename().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace sweetspot
