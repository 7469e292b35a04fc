// A launch-monitor session on disk: JSON lines, one Open Connect message per line, as
// `shot --gspro --session` and `connect --record` append them and `sweetspot send` replays
// them. Both writers read the file first and refuse to append to anything else.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sweetspot {

struct SessionFile {
  std::string text;  ///< the file's bytes, ending in a newline when not empty ("" for a new file)
  struct Line {
    int number;            ///< 1-based line in the file
    nlohmann::json message;  ///< a JSON object
  };
  std::vector<Line> lines;  ///< the non-blank lines
};

/// Reads a session to append to. A missing file is an empty session; a non-regular file, one
/// over 256 MiB (10 000 shots are ~10 MB) or a non-blank line that is not a JSON object is
/// refused with InputError naming `path:line` and `why` (what the caller appends).
SessionFile read_session_file(const std::string& path, const std::string& why);

}  // namespace sweetspot
