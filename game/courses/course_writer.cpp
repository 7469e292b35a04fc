#include "game/courses/course_writer.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>

#include "game/content/gzip_file.hpp"
#include "game/util/atomic_file.hpp"

namespace sweetspot {
namespace {

std::string metres(double v) {
  const int n = std::snprintf(nullptr, 0, "\"%.3fm\"", v);
  std::string b(static_cast<std::size_t>(n) + 1, '\0');
  std::snprintf(b.data(), b.size(), "\"%.3fm\"", v);
  b.pop_back();
  return b;
}

// The material colours the built-in worlds use (scripts/gen_worlds.py).
const char* colour_of(const std::string& m) {
  if (m == "green") return "0.380 0.760 0.360";
  if (m == "fairway") return "0.320 0.620 0.260";
  if (m == "tee") return "0.360 0.660 0.300";
  if (m == "sand") return "0.860 0.790 0.560";
  if (m == "water") return "0.150 0.350 0.620";
  if (m == "out_of_bounds") return "0.450 0.450 0.480";
  if (m == "tree") return "0.120 0.280 0.110";
  if (m == "cart_path") return "0.550 0.540 0.520";
  if (m == "trunk") return "0.330 0.240 0.150";
  return "0.200 0.420 0.150";  // rough
}

// A TOML basic string.
std::string toml_text(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) continue;
    out += c;
  }
  return out + "\"";
}

// [[x, z], ...] in metres.
std::string points_text(const std::vector<LocalPoint>& pts) {
  std::string out = "[";
  for (std::size_t i = 0; i < pts.size(); ++i)
    out += (i ? ", [" : "[") + metres(pts[i].x) + ", " + metres(pts[i].z) + "]";
  return out + "]";
}

// `s` on one line, for a comment: control bytes dropped.
std::string one_line(const std::string& s) {
  std::string out;
  for (const char c : s)
    if (static_cast<unsigned char>(c) >= 0x20) out += c;
  return out;
}

}  // namespace

void write_world(const std::filesystem::path& dir, const std::string& name, const SurfaceMesh& mesh, const LocalPoint& min,
                 const LocalPoint& max, const LocalPoint& origin) {
  std::ostringstream obj;
  obj << "# " << one_line(name) << ": written by sweetspot course import\nmtllib world.mtl\n";
  char line[96];
  for (const Vec3& v : mesh.vertices) {
    std::snprintf(line, sizeof line, "v %.3f %.3f %.3f\n", v.x(), v.y(), v.z());  // to the millimetre
    obj << line;
  }
  std::ostringstream mtl;
  mtl << "# " << one_line(name) << ": written by sweetspot course import\n";
  for (const SurfaceMesh::Group& g : mesh.groups) {
    obj << "g " << g.material << "\nusemtl " << g.material << "\n";
    for (const auto& t : g.triangles) obj << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    mtl << "newmtl " << g.material << "\nKd " << colour_of(g.material) << "\nKa 0 0 0\nKs 0 0 0\n";
  }
  // Compressed: an 18-hole ground is ~4 MB of text and ~1 MB gzipped (the world loader
  // inflates it; `gunzip -k` gives the OBJ for a modelling tool).
  write_file_atomic(dir / "world.obj.gz", gzip_bytes(obj.str()));
  write_file_atomic(dir / "world.mtl", mtl.str());
  double low = 0.0, high = 0.0;
  for (const Vec3& v : mesh.vertices) {
    low = std::min(low, v.y());
    high = std::max(high, v.y());
  }
  std::ostringstream t;
  t << "# " << one_line(name) << ": written by sweetspot course import (x east, z south, y up; m)\n"
    << "name = " << toml_text(name) << "\nsport = \"golf\"\nmesh = \"world.obj.gz\"\n"
    << "origin = [" << metres(origin.x) << ", \"0m\", " << metres(origin.z) << "]   # hole 1's tee\n"
    << "bounds_min = [" << metres(min.x) << ", " << metres(low - 20.0) << ", " << metres(min.z) << "]\n"
    << "bounds_max = [" << metres(max.x) << ", " << metres(high + 400.0) << ", " << metres(max.z) << "]\n";
  write_file_atomic(dir / "world.toml", t.str());
}


void write_course(const std::filesystem::path& dir, const ImportResult& r) {
  std::ostringstream t;
  t << "# " << one_line(r.name) << ": written by sweetspot course import. Each hole: its par, stroke index, the tee\n"
    << "# spot and the cup [x, z] on world.toml (m east, m south).\n"
    << "name = " << toml_text(r.name) << "\n";
  for (const ImportedHole& h : r.holes) {
    t << "\n[[hole]]\nnumber = " << h.number << "\npar = " << h.par << "\n";
    if (h.index > 0) t << "index = " << h.index << "\n";
    char len[64];
    std::snprintf(len, sizeof len, "   # %s, %.0f m", h.element.c_str(), h.length);
    t << "world = \"world.toml\"" << len << "\ntee = [" << metres(h.tee.x) << ", " << metres(h.tee.z) << "]\npin = ["
      << metres(h.pin.x) << ", " << metres(h.pin.z) << "]\n";
    if (!h.bends.empty()) t << "bends = " << points_text(h.bends) << "   # where the hole's line turns\n";
    if (!h.more_pins.empty()) t << "pins = " << points_text(h.more_pins) << "   # pin sets 2..\n";
    if (!h.tee_sets.empty()) {
      t << "tees = [";
      for (std::size_t i = 0; i < h.tee_sets.size(); ++i)
        t << (i ? ", " : "") << "{name = " << toml_text(h.tee_sets[i].first) << ", at = [" << metres(h.tee_sets[i].second.x)
          << ", " << metres(h.tee_sets[i].second.z) << "]}";
      t << "]\n";
    }
  }
  write_file_atomic(dir / "course.toml", t.str());
}


}  // namespace sweetspot
