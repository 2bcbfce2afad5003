#pragma once
// The lines a run's ledgers keep (time by cause, the report's block table)
// lie side by side in a vector and are found by key through an index. To
// stay bounded a ledger drops some of them now and then: the kept lines
// move up in their order, and their index entries follow.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <memory_resource>
#include <unordered_map>
#include <utility>
#include <vector>

namespace nck::app {

// A ledger's index: a line's key -> its place in the vector. A long program
// adds and drops a line per block (200,000 for the common program), each a
// node of the map: the nodes come from a pool of the index's own and go
// back to it instead of to malloc.
class LineIndex {
 public:
  using Map = std::pmr::unordered_map<std::uint64_t, std::size_t>;
  LineIndex() = default;
  LineIndex(LineIndex&&) = default;  // the map keeps its pool
  LineIndex& operator=(LineIndex&&) = delete;
  Map* operator->() { return &map_; }
  Map& operator*() { return map_; }

 private:
  std::unique_ptr<std::pmr::unsynchronized_pool_resource> pool_ =
      std::make_unique<std::pmr::unsynchronized_pool_resource>();
  Map map_{pool_.get()};
};

// Keeps the lines keep(line) is true for, in their order. moved(from, to)
// hears of each kept line that moves, before it does (pointers into the
// vector follow it); the index then points at the new places and forgets
// the dropped lines.
template <class Line, class Keep, class Moved>
void keep_lines(std::vector<Line>& lines, LineIndex& lines_index, Keep keep, Moved moved) {
  constexpr std::size_t kDropped = ~std::size_t{0};
  std::vector<std::size_t> moved_to(lines.size(), kDropped);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (!keep(lines[i])) continue;
    moved_to[i] = kept;
    Line& to = lines[kept++];
    if (&to == &lines[i]) continue;
    moved(lines[i], to);
    to = std::move(lines[i]);
  }
  lines.resize(kept);
  LineIndex::Map& index = *lines_index;
  for (auto it = index.begin(); it != index.end();) {
    if (const std::size_t to = moved_to[it->second]; to != kDropped) {
      it->second = to;
      ++it;
    } else {
      it = index.erase(it);
    }
  }
}

}  // namespace nck::app
