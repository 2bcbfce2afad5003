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
                                      index_out_of_range, undeclared, memory_cap };

// The longest STRING[n] nck declares: a block holds at most 4,000
// characters, so no literal can be longer.
inline constexpr std::size_t kMaxStringChars = 4000;

struct VarValue {
  double num = 0;
  std::string str;
  bool is_string = false;
  std::uint32_t charged = 0;  // bytes counted against the cap (declared length, or longer text assigned)
};

class Variables {
 public:
  // max_elements / max_bytes: the caps on declared program variables
  // (elements / declared bytes of every scope together), so that a program
  // cannot take unbounded memory. A number is 8 bytes, a string element its
  // declared length or the longer text assigned to it.
  Variables(std::vector<std::string> axis_names, int max_zero_index, std::size_t max_elements,
            std::size_t max_bytes);

  // P parameters.
  VarStatus read_p(std::int64_t idx, double& out) const;
  void write_p(std::int64_t idx, double v) { p_[idx] = v; }

  // Any V. name (normalised key, see above).
  VarStatus read(const std::string& key, double& out) const;
  VarStatus write(const std::string& key, double v);
  VarStatus write_string(const std::string& key, std::string v);
  // Declares a variable (#VAR). dims empty = scalar. Elements start at 0 / "";
  // string_chars: a STRING's declared length (0: none given).
  enum class Declared : std::uint8_t { ok, array_too_large, memory_cap };
  Declared declare(const std::string& base, const std::vector<int>& dims, bool is_string,
                   std::size_t string_chars = 0);
  std::size_t declared_bytes() const;
  bool is_kernel(std::string_view key) const;
  bool known_kernel(const std::string& key) const;
  void set_state_reader(const KernelStateReader* reader) { state_reader_ = reader; }

  // V.L. scope per call level; a cycle call's level also holds its @P
  // transfer parameters (readable only while that level is the innermost).
  using CycleParams = std::unordered_map<std::int64_t, double>;
  void push_scope() {
    locals_.emplace_back();
    local_bytes_.push_back(0);
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
      local_bytes_.pop_back();
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
  std::size_t& bytes_of(const Map* m);  // the byte count of the scope m is
  void forget(const std::string& base, Map& m);  // a declaration's elements, before it is declared again

  std::vector<std::string> axes_;
  int max_zero_index_;
  std::size_t max_elements_;
  std::size_t max_bytes_;
  std::unordered_map<std::int64_t, double> p_;
  std::vector<Map> locals_;  // V.L. and V.CYC., one map per call level
  std::vector<std::size_t> local_bytes_;  // declared bytes per call level (parallel to locals_)
  std::size_t global_bytes_ = 0;
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
