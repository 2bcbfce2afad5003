#pragma once
// What a run says on stderr (diagnostics, limits, the summary): printed by
// `nck run`, kept in order by the Python module (Run.messages), which must
// not write on a notebook's stderr behind the user's back.
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace nck::app {

class Console {
 public:
  explicit Console(bool keep = false) : keep_(keep) {}
  void line(std::string text) {
    if (keep_) lines_.push_back(std::move(text));
    else fmt::print(stderr, "{}\n", text);
  }
  std::vector<std::string> take() { return std::exchange(lines_, {}); }

 private:
  bool keep_;
  std::vector<std::string> lines_;
};

}  // namespace nck::app
