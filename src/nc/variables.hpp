#pragma once
// Variable stores of the decoder: P parameters, program variables declared
// in #VAR (V.L. per call level, V.P./V.S./V.CYC. program-wide) and the
// kernel variables (V.G./V.A.) that the kernel reads and writes by name.
// Names are normalised to upper case with evaluated indices:
// "V.P.ARR[2][0]", "V.G.NP[1].V.X".
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "nck/nc/decoder.hpp"

namespace nck::nc::detail {

enum class VarStatus : std::uint8_t { ok, undefined, unknown_kernel, is_string, not_string,
                                      index_out_of_range, undeclared };

struct VarValue {
  double num = 0;
  std::string str;
  bool is_string = false;
};

class Variables {
 public:
  // max_elements: the cap on declared program variables (elements of every
  // scope together), so that a program cannot take unbounded memory.
  Variables(std::vector<std::string> axis_names, int max_zero_index, std::size_t max_elements);

  // P parameters.
  VarStatus read_p(std::int64_t idx, double& out) const;
  void write_p(std::int64_t idx, double v) { p_[idx] = v; }

  // Any V. name (normalised key, see above).
  VarStatus read(const std::string& key, double& out) const;
  VarStatus write(const std::string& key, double v);
  VarStatus write_string(const std::string& key, std::string v);
  // Declares a variable (#VAR). dims empty = scalar. Elements start at 0 / "".
  enum class Declared : std::uint8_t { ok, array_too_large, memory_cap };
  Declared declare(const std::string& base, const std::vector<int>& dims, bool is_string);
  bool is_kernel(std::string_view key) const;
  bool known_kernel(const std::string& key) const;
  void set_state_reader(const KernelStateReader* reader) { state_reader_ = reader; }

  // V.L. scope per call level; a cycle call's level also holds its @P
  // transfer parameters (readable only while that level is the innermost).
  using CycleParams = std::unordered_map<std::int64_t, double>;
  void push_scope() {
    locals_.emplace_back();
    cycles_.emplace_back();
  }
  void push_cycle_scope(CycleParams params) {
    push_scope();
    cycles_.back().active = true;
    cycles_.back().p = std::move(params);
  }
  void pop_scope() {
    if (locals_.size() > 1) {
      locals_.pop_back();
      cycles_.pop_back();
    }
  }
  bool in_cycle() const { return cycles_.back().active; }
  // @P<idx> of the innermost cycle: ok, undefined (not given), undeclared (not in a cycle).
  VarStatus read_cycle_p(std::int64_t idx, double& out) const;
  VarStatus write_cycle_p(std::int64_t idx, double v);

 private:
  using Map = std::unordered_map<std::string, VarValue>;
  Map* scope_for(std::string_view key);
  const Map* scope_for(std::string_view key) const;
  VarStatus check_index(const Map& m, const std::string& key) const;

  std::size_t declared_elements() const;

  std::vector<std::string> axes_;
  int max_zero_index_;
  std::size_t max_elements_;
  std::unordered_map<std::int64_t, double> p_;
  std::vector<Map> locals_;  // V.L. and V.CYC., one map per call level
  struct CycleScope {
    bool active = false;  // this level is a cycle
    CycleParams p;        // its @P values
  };
  std::vector<CycleScope> cycles_;  // parallel to locals_
  Map globals_;              // V.P., V.S.
  std::unordered_map<std::string, double> kernel_;  // V.G., V.A.
  const KernelStateReader* state_reader_ = nullptr;  // the channel's state variables
  // declared array dimensions by base name, for index checks
  std::unordered_map<std::string, std::vector<int>> dims_;
};

}  // namespace nck::nc::detail
