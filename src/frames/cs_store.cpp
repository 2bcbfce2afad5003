#include "nck/frames/cs_store.hpp"

#include <cctype>
#include <cmath>

namespace nck::frames {
namespace {

bool finite(const CsValues& v) {
  for (double x : v.shift_mm)
    if (!std::isfinite(x)) return false;
  for (double x : v.angle_deg)
    if (!std::isfinite(x)) return false;
  return true;
}

bool equals_nocase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::toupper(static_cast<unsigned char>(a[i])) !=
        std::toupper(static_cast<unsigned char>(b[i])))
      return false;
  return true;
}

}  // namespace

Vec3 RigidFrame::to_parent(const Vec3& p) const {
  Vec3 r = mul(rot, p);
  return {r[0] + shift_mm[0], r[1] + shift_mm[1], r[2] + shift_mm[2]};
}

Vec3 RigidFrame::to_child(const Vec3& p) const {
  Vec3 d{p[0] - shift_mm[0], p[1] - shift_mm[1], p[2] - shift_mm[2]};
  return mul(transpose(rot), d);
}

RigidFrame make_frame(const CsValues& v, const RotationConvention& c) {
  return RigidFrame{v.shift_mm, rotation_matrix(c, v.angle_deg)};
}

const CsStore::Definition* CsStore::find(int id) const {
  for (const auto& d : defs_)
    if (d.id == id) return &d;
  return nullptr;
}

CsStore::Definition* CsStore::find_mut(int id) {
  for (auto& d : defs_)
    if (d.id == id) return &d;
  return nullptr;
}

int CsStore::next_free_id() const {
  int id = 1;
  while (find(id) != nullptr) ++id;
  return id;
}

std::expected<void, FrameError> CsStore::push(const Definition& d, std::string_view name) {
  if (active_.full()) return std::unexpected(FrameError{ErrorId::FrCsNestingTooDeep, -1, d.id});
  Active a{d.id, d.values, d.frame, {}};
  for (std::size_t i = 0; i < name.size() && i < kMaxName; ++i) a.name[i] = name[i];
  active_.push_back(a);
  selected_depth_.reset();
  return {};
}

std::expected<void, FrameError> CsStore::define(std::optional<int> id, const CsValues& v,
                                                const RotationConvention& c, bool activate) {
  if (id && *id <= 0) return std::unexpected(FrameError{ErrorId::FrCsIdInvalid, -1, *id});
  if (!finite(v)) return std::unexpected(FrameError{ErrorId::FrValueNotFinite, -1, id.value_or(0)});
  if (activate && active_.full())
    return std::unexpected(FrameError{ErrorId::FrCsNestingTooDeep, -1, id.value_or(0)});
  Definition d{id.value_or(next_free_id()), v, make_frame(v, c), !id.has_value()};
  if (Definition* existing = find_mut(d.id)) {
    *existing = d;  // redefinition replaces the stored values
  } else if (!defs_.push_back(d)) {
    return std::unexpected(FrameError{ErrorId::FrTooManyCsDefinitions, -1, d.id});
  }
  last_defined_ = d.id;
  if (activate) return push(d, {});
  return {};
}

std::expected<void, FrameError> CsStore::activate(std::optional<int> id) {
  if (id && *id <= 0) return std::unexpected(FrameError{ErrorId::FrCsIdInvalid, -1, *id});
  int want = id ? *id : last_defined_.value_or(0);
  const Definition* d = find(want);
  if (d == nullptr) return std::unexpected(FrameError{ErrorId::FrUnknownCsId, -1, want});
  return push(*d, {});
}

bool CsStore::deactivate() {
  if (active_.empty()) return false;
  int id = active_.back().id;
  active_.pop_back();
  selected_depth_.reset();
  // A CS created without an id lives only until it is switched off, unless
  // it is still active further down the stack.
  const Definition* d = find(id);
  bool still_used = false;
  for (const auto& a : active_) still_used = still_used || a.id == id;
  if (d != nullptr && d->temporary && !still_used) {
    FixedVector<Definition, kMaxDefinitions> kept;
    for (const auto& x : defs_)
      if (x.id != id) kept.push_back(x);
    defs_ = kept;
    if (last_defined_ == id) last_defined_.reset();
  }
  return true;
}

std::size_t CsStore::deactivate_all() {
  std::size_t n = 0;
  while (deactivate()) ++n;
  return n;
}

std::expected<void, FrameError> CsStore::add(std::string_view name, const CsValues& v,
                                             const RotationConvention& c) {
  if (name.empty() || name.size() > kMaxName || equals_nocase(name, "ACS") ||
      equals_nocase(name, "MCS") || equals_nocase(name, "IMCS"))
    return std::unexpected(FrameError{ErrorId::FrCsNameInvalid});
  if (!finite(v)) return std::unexpected(FrameError{ErrorId::FrValueNotFinite});
  return push(Definition{0, v, make_frame(v, c), true}, name);
}

std::expected<void, FrameError> CsStore::select(std::string_view name) {
  if (equals_nocase(name, "MCS") || equals_nocase(name, "IMCS")) {
    selected_depth_ = 0;
    return {};
  }
  for (std::size_t i = 0; i < active_.size(); ++i) {
    if (equals_nocase(name, std::string_view(active_[i].name.data()))) {
      selected_depth_ = i + 1;
      return {};
    }
  }
  return std::unexpected(FrameError{ErrorId::FrUnknownCsName});
}

}  // namespace nck::frames
