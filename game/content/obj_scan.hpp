// A pass over an OBJ's text before the importer (assimp) reads it: assimp reports a short
// vertex line or a face that points past the vertices as "vertex index out of range" with no
// line, and spends time in the square of the object count. This pass names the line.
#pragma once

#include <filesystem>
#include <string_view>

namespace sweetspot {

/// Refuses, naming PATH:LINE and what is wrong: a vertex line ('v') with fewer than three
/// coordinates or one that is not a number; a statement that begins like a vertex but is none
/// ("vx"); a face corner ('f') whose vertex index is zero, not a whole number, or refers to
/// a vertex not defined before it; more than kMaxObjObjects objects ('o' lines). Only the
/// object count applies to a file not named *.obj (assimp also recognises an OBJ by its
/// contents). `what` names the file's role ("world mesh").
void check_obj_text(const std::filesystem::path& path, const char* what);
/// The same checks of a file's text already in memory (an inflated "world.obj.gz"): `path`
/// names it in messages, and its name without ".gz" decides whether it is an OBJ.
void check_obj_text(std::string_view text, const std::filesystem::path& path, const char* what);

}  // namespace sweetspot
