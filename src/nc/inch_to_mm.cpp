// Part of stage 3 (apply): under G70 the block's lengths are converted to mm
// here, once, so that every Block leaves the decoder in mm and no later layer
// needs to know the program unit (modal.inch stays as information).
#include "block_words.hpp"

namespace nck::nc::detail {
namespace {

constexpr double kInchMm = 25.4;

// Non-modal functions whose axis words are not lengths: G4 dwell time, G74
// homing order, G101 factor, G102 selection, G200 dummy values.
constexpr GCodeSet kAxisWordsNotLengths{GCode::g4,   GCode::g74,  GCode::g101, GCode::g102,
                                        GCode::g130, GCode::g132, GCode::g200};

void scale(At<double>& a) {
  if (a.v) *a.v *= kInchMm;
}
void scale(std::optional<double>& v) {
  if (v) *v *= kInchMm;
}

bool axis_words_are_lengths(const Words& w) {
  for (const auto& g : w.g)
    if (kAxisWordsNotLengths.has(g.code) || g_group(g.code) == GGroup::manual) return false;
  return true;
}

// The # commands that carry lengths in program units.
void hash_to_mm(HashCommand& h) {
  if (auto* cs = std::get_if<CoordSystem>(&h)) {
    for (std::size_t i = 0; i < 3; ++i) cs->values[i] *= kInchMm;  // translations; angles stay deg
  } else if (auto* r = std::get_if<Rotation>(&h)) {
    scale(r->center1_mm);
    scale(r->center2_mm);
  } else if (auto* t = std::get_if<Tlc>(&h)) {
    t->delta_mm *= kInchMm;
  }
}

}  // namespace

void words_to_mm(Words& w, const ModalState& modal) {
  // under G93 F is a time, under G194 a percentage
  if (modal.feed_mode != FeedMode::g93 && modal.feed_mode != FeedMode::g194) scale(w.f);
  scale(w.r);
  for (auto& c : w.ijk) scale(c);
  // #PSET takes its values from the axis words, so they are converted here
  // too. Rotary axes are scaled as well, as the kernel did before the
  // conversion moved here (the decoder does not know the axis kinds).
  if (axis_words_are_lengths(w))
    for (auto& a : w.axes) scale(a);
  if (w.hash) hash_to_mm(*w.hash);
}

void kernel_writes_to_mm(std::vector<VariableWrite>& writes) {
  // V.G.NP[i].V.<axis>: zero-offset table entries are lengths.
  for (VariableWrite& kw : writes)
    if (kw.name.starts_with("V.G.NP[")) kw.value *= kInchMm;
}

}  // namespace nck::nc::detail
