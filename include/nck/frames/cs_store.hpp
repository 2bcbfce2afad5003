#pragma once
// Definitions and the activation stack of one family of coordinate systems
// (#CS or #ACS; both have the same grammar and limits, FCT-C2 §2.2.1/2.2.3).
#include <array>
#include <cstdint>
#include <expected>
#include <optional>
#include <string_view>

#include "nck/core/fixed_vector.hpp"
#include "nck/frames/rotation.hpp"
#include "nck/frames/types.hpp"

namespace nck::frames {

// #CS [v1,v2,v3,phi1,phi2,phi3]: translation along the main axes in G17
// order, then the three angles.
struct CsValues {
  Vec3 shift_mm{};
  Vec3 angle_deg{};
};

// A translation plus a rotation: parent = shift + rot * child. The shift
// moves the origin in the parent's axes, then the axes turn about it.
struct RigidFrame {
  Vec3 shift_mm{};
  Mat3 rot = identity3();
  Vec3 to_parent(const Vec3& p) const;
  Vec3 to_child(const Vec3& p) const;  // exact inverse (rot is orthonormal)
};

RigidFrame make_frame(const CsValues& v, const RotationConvention& c);

class CsStore {
 public:
  static constexpr std::size_t kMaxDefinitions = 5;  // TF5200 #CS DEF; docs/coordinate-systems.md
  static constexpr std::size_t kMaxActive = 5;
  static constexpr std::size_t kMaxName = 8;  // #CS ADD names (TF5200 #CS ADD)

  struct Definition {
    int id = 0;
    CsValues values;
    RigidFrame frame;
    bool temporary = false;  // created without an id: gone after its OFF
  };
  struct Active {
    int id = 0;
    CsValues values;
    RigidFrame frame;
    std::array<char, kMaxName + 1> name{};  // #CS ADD name, "" otherwise
  };

  // #CS DEF [[id]] [..] (activate=false) and #CS ON [[id]] [..] (true).
  // The frame is computed with the convention in force now.
  std::expected<void, FrameError> define(std::optional<int> id, const CsValues& v,
                                         const RotationConvention& c, bool activate);
  // #CS ON [id] (stored one) or #CS ON (the one defined last).
  std::expected<void, FrameError> activate(std::optional<int> id);
  // #CS OFF: the CS activated last. Returns false when none was active.
  bool deactivate();
  // #CS OFF ALL. Returns how many were active.
  std::size_t deactivate_all();
  // #CS ADD [name][..]: push a named CS relative to the one before it.
  std::expected<void, FrameError> add(std::string_view name, const CsValues& v,
                                      const RotationConvention& c);
  // #CS SELECT [name]: program in the chain up to `name`; MCS/IMCS = none.
  std::expected<void, FrameError> select(std::string_view name);

  // Stack entries that act on programmed positions, bottom (outermost) first.
  std::size_t effective_depth() const { return selected_depth_.value_or(active_.size()); }
  std::size_t depth() const { return active_.size(); }
  const Active& active(std::size_t i) const { return active_[i]; }
  std::size_t definition_count() const { return defs_.size(); }
  const Definition* find(int id) const;

 private:
  Definition* find_mut(int id);
  int next_free_id() const;
  std::expected<void, FrameError> push(const Definition& d, std::string_view name);

  FixedVector<Definition, kMaxDefinitions> defs_;
  FixedVector<Active, kMaxActive> active_;
  std::optional<int> last_defined_;
  std::optional<std::size_t> selected_depth_;  // set by SELECT, cleared by ON/ADD/OFF
};

}  // namespace nck::frames
