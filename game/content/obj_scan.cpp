#include "game/content/obj_scan.hpp"

#include <charconv>
#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "game/content/gzip_file.hpp"
#include "game/content/mesh_file.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// The next whitespace-separated word of `rest` (empty at the end), advancing `rest`.
std::string_view next_word(std::string_view& rest) {
  std::size_t i = 0;
  while (i < rest.size() && blank(rest[i])) ++i;
  std::size_t j = i;
  while (j < rest.size() && !blank(rest[j])) ++j;
  const std::string_view word = rest.substr(i, j - i);
  rest.remove_prefix(j);
  return word;
}

struct ObjScan {
  const std::filesystem::path& path;
  const char* what;
  bool obj_syntax;  // the file is named *.obj: its lines are checked, not only counted
  std::uint64_t line = 1, objects = 0, vertices = 0;

  [[noreturn]] void fail(const std::string& why) const {
    throw InputError(path.string() + ":" + std::to_string(line) + ": " + why);
  }

  void statement(std::string_view text) {
    std::string_view rest = text;
    const std::string_view keyword = next_word(rest);
    if (keyword == "o") {
      if (++objects > kMaxObjObjects)
        fail(std::string("the ") + what + " has over " + std::to_string(kMaxObjObjects) +
             " objects ('o' lines; the limit: the OBJ reader slows with their square); join them "
             "(one object per surface is enough: usemtl gives the material) or use groups ('g')");
      return;
    }
    if (!obj_syntax) return;
    if (keyword == "v") {
      for (int k = 0; k < 3; ++k) {
        const std::string_view word = next_word(rest);
        if (word.empty()) fail("a vertex ('v') needs x, y and z; this one has " + std::to_string(k));
        double x = 0.0;
        const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), x);
        // Out of a double's range is a number still: the importer's finite check names it.
        if ((ec != std::errc() && ec != std::errc::result_out_of_range) || end != word.data() + word.size())
          fail("vertex coordinate '" + std::string(word.substr(0, 24)) + "' is not a number");
      }
      ++vertices;
    } else if (keyword == "f") {
      int corner = 0;
      for (std::string_view word = next_word(rest); !word.empty(); word = next_word(rest)) {
        ++corner;
        const std::string_view index = word.substr(0, word.find('/'));
        long long i = 0;
        const auto [end, ec] = std::from_chars(index.data(), index.data() + index.size(), i);
        if (ec != std::errc() || end != index.data() + index.size() || i == 0)
          fail("face corner " + std::to_string(corner) + " '" + std::string(word.substr(0, 24)) +
               "': a vertex index is a whole number, 1 or more (or negative, counting back)");
        const long long n = static_cast<long long>(vertices);
        if (i > n || i < -n)
          fail("face corner " + std::to_string(corner) + " refers to vertex " + std::to_string(i) + ", but " +
               std::to_string(vertices) + " vertices are defined before this line");
      }
    } else if (keyword.size() > 1 && keyword[0] == 'v' && keyword != "vt" && keyword != "vn" && keyword != "vp") {
      fail("unknown statement '" + std::string(keyword.substr(0, 24)) + "' (a vertex is 'v x y z')");
    }
  }
};

}  // namespace

namespace {

// The statements of an OBJ's text fed a block at a time: only lines that begin with 'o', 'v'
// or 'f' are kept.
class ObjTextScan {
 public:
  ObjTextScan(const std::filesystem::path& path, const char* what, bool obj_syntax) : scan_{path, what, obj_syntax} {}
  void feed(const char* block, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
      const char c = block[i];
      if (line_start_) {
        keep_ = c == 'o' || c == 'v' || c == 'f';
        line_start_ = false;
      }
      if (c == '\n') {
        // A backslash before the newline continues the statement on the next line (which
        // then names it).
        const std::size_t end = text_.find_last_not_of(" \t\r");
        if (keep_ && end != std::string::npos && text_[end] == '\\') {
          text_.resize(end);
          text_ += ' ';
          ++scan_.line;
          continue;
        }
        if (keep_) scan_.statement(text_);
        text_.clear();
        ++scan_.line;
        line_start_ = true;
      } else if (keep_) {
        text_ += c;
      }
    }
  }
  void finish() {
    if (keep_ && !text_.empty()) scan_.statement(text_);
  }

 private:
  ObjScan scan_;
  std::string text_;  // the statement being read
  bool keep_ = true, line_start_ = true;
};

}  // namespace

void check_obj_text(const std::filesystem::path& path, const char* what) {
  std::ifstream in(path, std::ios::binary);
  ObjTextScan scan(path, what, path.extension() == ".obj");
  std::vector<char> block(1 << 16);  // a block at a time: a world's mesh is read at every start
  while (in.read(block.data(), static_cast<std::streamsize>(block.size())) || in.gcount() > 0)
    scan.feed(block.data(), static_cast<std::size_t>(in.gcount()));
  scan.finish();
}

void check_obj_text(std::string_view text, const std::filesystem::path& path, const char* what) {
  ObjTextScan scan(path, what, without_gzip_suffix(path).extension() == ".obj");
  scan.feed(text.data(), text.size());
  scan.finish();
}

}  // namespace sweetspot
