#include "datasets/io/json_file.h"

#include <set>
#include <vector>

#include "datasets/io/io_error.h"

namespace implicitfit {
namespace {

using nlohmann::json;

// The keys seen in every open object and the position in every open container: the JSON path
// of a duplicate is built from them only when one is found (memory stays linear in the depth
// of a 10^5-deep document).
struct Frame {
  bool object = false;
  std::set<std::string> keys;
  std::string key;  // object: the last key
  long index = -1;  // array: the index of the last element
};

// The path of the innermost open container ("root.children[1]").
std::string PathOf(const std::vector<Frame>& stack) {
  std::string path;
  for (size_t i = 0; i + 1 < stack.size(); ++i) {
    const Frame& f = stack[i];
    if (f.object)
      path += (path.empty() ? "" : ".") + f.key;
    else
      path += "[" + std::to_string(f.index) + "]";
  }
  return path;
}

class DuplicateKey : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace

json ParseJsonDocument(const std::string& text, const std::string& path) {
  std::vector<Frame> stack;
  const json::parser_callback_t callback = [&stack](int, json::parse_event_t event,
                                                    json& parsed) {
    switch (event) {
      case json::parse_event_t::key: {
        Frame& f = stack.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second) {
          const std::string where = PathOf(stack);
          throw DuplicateKey("duplicate key \"" + f.key.substr(0, 60) + "\" in " +
                             (where.empty() ? "the top-level object" : where.substr(0, 200)));
        }
        break;
      }
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start: {
        if (!stack.empty() && !stack.back().object) ++stack.back().index;
        Frame f;
        f.object = event == json::parse_event_t::object_start;
        stack.push_back(std::move(f));
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        stack.pop_back();
        break;
      case json::parse_event_t::value:
        if (!stack.empty() && !stack.back().object) ++stack.back().index;
        break;
    }
    return true;
  };
  try {
    return json::parse(text, callback);
  } catch (const DuplicateKey& e) {
    throw FileError(path, std::string("invalid JSON: ") + e.what());
  } catch (const json::exception& e) {
    // e.what() reads "[json.exception.parse_error.101] parse error at line L, column C: ..."
    // or, for a number beyond the double range (found by the model fuzzer),
    // "[json.exception.out_of_range.406] number overflow parsing '1e3081'".
    const std::string what = e.what();
    const size_t at = what.find("] ");
    throw FileError(path,
                    "invalid JSON: " + (at == std::string::npos ? what : what.substr(at + 2)));
  }
}

}  // namespace implicitfit
