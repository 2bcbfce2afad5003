#include <fmt/format.h>
#include "variables.hpp"

#include "lexer.hpp"

namespace nck::nc::detail {

namespace {
constexpr std::size_t kMaxArrayElements = 100000;

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

// "NAME[1][2].X" -> base "NAME" and indices; false if malformed.
bool split_indices(std::string_view key, std::string_view& base, std::vector<int>& idx) {
  std::size_t b = key.find('[');
  if (b == std::string_view::npos) {
    base = key;
    return true;
  }
  base = key.substr(0, b);
  std::size_t p = b;
  while (p < key.size() && key[p] == '[') {
    std::size_t e = key.find(']', p);
    if (e == std::string_view::npos) return false;
    int v = 0;
    for (std::size_t i = p + 1; i < e; ++i) {
      if (key[i] == '-') return false;
      v = v * 10 + (key[i] - '0');
      if (v > 1'000'000) return false;
    }
    idx.push_back(v);
    p = e + 1;
  }
  return true;
}
}  // namespace

Variables::Variables(std::vector<std::string> axis_names, int max_zero_index, std::size_t max_elements,
                     std::size_t max_bytes)
    : axes_(std::move(axis_names)), max_zero_index_(max_zero_index), max_elements_(max_elements),
      max_bytes_(max_bytes) {
  for (auto& a : axes_) a = to_upper(a);
  locals_.emplace_back();
  local_bytes_.push_back(0);
  cycles_.emplace_back();
}

VarStatus Variables::read_cycle_p(std::int64_t idx, double& out) const {
  const CycleScope& c = cycles_.back();
  if (!c.active) return VarStatus::undeclared;
  auto it = c.p.find(idx);
  if (it == c.p.end()) return VarStatus::undefined;
  out = it->second;
  return VarStatus::ok;
}

VarStatus Variables::write_cycle_p(std::int64_t idx, double v) {
  CycleScope& c = cycles_.back();
  if (!c.active) return VarStatus::undeclared;
  c.p[idx] = v;
  return VarStatus::ok;
}

VarStatus Variables::read_p(std::int64_t idx, double& out) const {
  auto it = p_.find(idx);
  if (it == p_.end()) return VarStatus::undefined;
  out = it->second;
  return VarStatus::ok;
}

bool Variables::is_kernel(std::string_view key) const {
  return starts_with(key, "V.G.") || starts_with(key, "V.A.");
}

// The kernel variables nck knows (the ones the offsets and measuring
// functions use); anything else under V.G./V.A. is reported as unknown
// instead of silently reading 0.
bool Variables::known_kernel(const std::string& key) const {
  auto is_axis = [&](std::string_view a) {
    for (const auto& n : axes_)
      if (n == a) return true;
    return false;
  };
  static constexpr std::string_view kScalars[] = {
      "V.G.AKT_PLATZ", "V.G.NP_DEFAULT", "V.G.ROT_ACTIVE", "V.G.ROT_ANGLE", "V.G.ROT_CENTER1",
      "V.G.ROT_CENTER2", "V.G.WZ_AKT.R", "V.G.WZ_AKT.L", "V.G.WZ_AKT.NR"};
  for (auto s : kScalars)
    if (key == s) return true;
  std::string_view k = key;
  static constexpr std::string_view kAxisGroups[] = {"V.A.MESS.", "V.A.MERF.", "V.A.MOFFS.",
                                                     "V.A.MEIN.", "V.A.MANUAL_OFFSETS.",
                                                     "V.A.ABS.", "V.G.NP_AKT.V."};
  for (auto g : kAxisGroups)
    if (starts_with(k, g)) return is_axis(k.substr(g.size()));
  if (starts_with(k, "V.G.NP[")) {
    std::size_t e = k.find(']');
    if (e == std::string_view::npos) return false;
    int idx = 0;
    for (std::size_t i = 7; i < e; ++i) {
      if (!is_digit(k[i])) return false;
      idx = idx * 10 + (k[i] - '0');
      if (idx > max_zero_index_) return false;
    }
    if (!starts_with(k.substr(e + 1), ".V.")) return false;
    return is_axis(k.substr(e + 4));
  }
  return false;
}

Variables::Map* Variables::scope_for(std::string_view key) {
  if (starts_with(key, "V.L.") || starts_with(key, "V.CYC.")) return &locals_.back();
  if (starts_with(key, "V.P.") || starts_with(key, "V.S.")) return &globals_;
  return nullptr;
}
const Variables::Map* Variables::scope_for(std::string_view key) const {
  return const_cast<Variables*>(this)->scope_for(key);
}

VarStatus Variables::check_index(const Map& m, const std::string& key) const {
  (void)m;
  std::string_view base;
  std::vector<int> idx;
  if (!split_indices(key, base, idx)) return VarStatus::index_out_of_range;
  auto it = dims_.find(std::string(base));
  if (it == dims_.end()) return VarStatus::undeclared;
  const auto& d = it->second;
  if (d.size() != idx.size()) return VarStatus::index_out_of_range;
  for (std::size_t i = 0; i < d.size(); ++i)
    if (idx[i] >= d[i]) return VarStatus::index_out_of_range;
  return VarStatus::undeclared;
}

VarStatus Variables::read(const std::string& key, double& out) const {
  if (is_kernel(key)) {
    if (!known_kernel(key)) return VarStatus::unknown_kernel;
    if (state_reader_)
      if (const std::optional<double> v = state_reader_->read(key)) {
        out = *v;
        return VarStatus::ok;
      }
    auto it = kernel_.find(key);
    out = it == kernel_.end() ? 0.0 : it->second;
    return VarStatus::ok;
  }
  const Map* m = scope_for(key);
  if (!m) return VarStatus::undeclared;
  auto it = m->find(key);
  if (it == m->end()) {
    VarStatus s = check_index(*m, key);
    return s == VarStatus::undeclared ? VarStatus::undefined : s;
  }
  if (it->second.is_string) return VarStatus::is_string;
  out = it->second.num;
  return VarStatus::ok;
}

VarStatus Variables::write(const std::string& key, double v) {
  if (is_kernel(key)) {
    if (!known_kernel(key)) return VarStatus::unknown_kernel;
    kernel_[key] = v;
    return VarStatus::ok;
  }
  Map* m = scope_for(key);
  if (!m) return VarStatus::undeclared;
  auto it = m->find(key);
  if (it == m->end()) return check_index(*m, key);
  if (it->second.is_string) return VarStatus::is_string;
  it->second.num = v;
  return VarStatus::ok;
}

VarStatus Variables::write_string(const std::string& key, std::string v) {
  Map* m = scope_for(key);
  if (!m) return VarStatus::undeclared;
  auto it = m->find(key);
  if (it == m->end()) return check_index(*m, key);
  VarValue& var = it->second;
  if (!var.is_string) return VarStatus::not_string;
  if (v.size() > var.charged) {  // longer than declared: the text counts
    if (declared_bytes() + (v.size() - var.charged) > max_bytes_) return VarStatus::memory_cap;
    bytes_of(m) += v.size() - var.charged;
    var.charged = static_cast<std::uint32_t>(v.size());
  }
  var.str = std::move(v);
  return VarStatus::ok;
}

// Removes the scalar or every array element `base` names in m, and their
// bytes (dims from the last declaration of `base`).
void Variables::forget(const std::string& base, Map& m) {
  auto drop = [&](const std::string& key) {
    auto it = m.find(key);
    if (it == m.end()) return;
    bytes_of(&m) -= it->second.charged;
    m.erase(it);
  };
  drop(base);
  auto d = dims_.find(base);
  if (d == dims_.end() || d->second.empty()) return;
  const std::vector<int>& dims = d->second;
  std::string first = base;
  for (std::size_t i = 0; i < dims.size(); ++i) first += "[0]";
  if (!m.contains(first)) return;  // an array of this name in another scope
  std::vector<int> idx(dims.size(), 0);
  for (bool more = true; more;) {
    std::string key = base;
    for (int i : idx) key += fmt::format("[{}]", i);
    drop(key);
    more = false;
    for (std::size_t k = dims.size(); k-- > 0;) {
      if (++idx[k] < dims[k]) {
        more = true;
        break;
      }
      idx[k] = 0;
    }
  }
}

std::size_t& Variables::bytes_of(const Map* m) {
  for (std::size_t i = 0; i < locals_.size(); ++i)
    if (&locals_[i] == m) return local_bytes_[i];
  return global_bytes_;
}

std::size_t Variables::declared_bytes() const {
  std::size_t n = global_bytes_;
  for (std::size_t b : local_bytes_) n += b;
  return n;
}

std::size_t Variables::declared_elements() const {
  std::size_t n = globals_.size();
  for (const Map& m : locals_) n += m.size();
  return n;
}

Variables::Declared Variables::declare(const std::string& base, const std::vector<int>& dims, bool is_string,
                                       std::size_t string_chars) {
  Map* m = scope_for(base);
  if (!m) return Declared::array_too_large;
  std::size_t total = 1;
  for (int d : dims) {
    if (d < 1) return Declared::array_too_large;
    total *= static_cast<std::size_t>(d);
    if (total > kMaxArrayElements) return Declared::array_too_large;
  }
  forget(base, *m);  // declared again (a #VAR in a loop): the old one goes
  if (declared_elements() + total > max_elements_) return Declared::memory_cap;
  const std::size_t element_bytes = is_string ? string_chars : sizeof(double);
  if (declared_bytes() + total * element_bytes > max_bytes_) return Declared::memory_cap;
  bytes_of(m) += total * element_bytes;
  VarValue init;
  init.is_string = is_string;
  init.charged = static_cast<std::uint32_t>(element_bytes);
  if (dims.empty()) {
    (*m)[base] = init;
    return Declared::ok;
  }
  dims_[base] = dims;
  std::vector<int> idx(dims.size(), 0);
  for (std::size_t n = 0; n < total; ++n) {
    std::string key = base;
    for (int i : idx) key += fmt::format("[{}]", i);
    (*m)[key] = init;
    for (std::size_t k = dims.size(); k-- > 0;) {
      if (++idx[k] < dims[k]) break;
      idx[k] = 0;
    }
  }
  return Declared::ok;
}

}  // namespace nck::nc::detail
