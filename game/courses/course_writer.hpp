// What course import writes (DESIGN §9): a world (world.toml naming world.obj, the ground by
// material, and world.mtl, its colours) and course.toml, the holes over it. Each file is
// written atomically; the caller writes them into a directory it renames into place.
#pragma once

#include <filesystem>
#include <string>

#include "game/courses/course_import.hpp"
#include "game/courses/surface_plan.hpp"

namespace sweetspot {

/// world.toml, world.obj and world.mtl in `dir`: the mesh, the box [min, max] it spans (with
/// room below its lowest ground and 400 m of air above its highest), `origin` hole 1's tee.
void write_world(const std::filesystem::path& dir, const std::string& name, const SurfaceMesh& mesh, const LocalPoint& min,
                 const LocalPoint& max, const LocalPoint& origin);

/// course.toml in `dir`: each hole's number, par, stroke index (when mapped), tee and cup on
/// world.toml.
void write_course(const std::filesystem::path& dir, const ImportResult& result);

}  // namespace sweetspot
