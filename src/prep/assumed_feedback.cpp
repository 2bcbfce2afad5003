#include "nck/prep/assumed_feedback.hpp"

namespace nck::prep {

kernel::Feedback assumed_feedback(const nc::Block& b, const Planner& planner) {
  kernel::Feedback f;
  if (b.g_nonmodal.has(nc::GCode::g100)) {
    f.kind = kernel::FeedbackKind::measured;
    f.measure.triggered = true;
    f.measure.mcs = planner.planned_mcs();
  } else if (b.hash && std::holds_alternative<nc::CAxis>(*b.hash)) {
    f.kind = kernel::FeedbackKind::c_axis;
  } else {
    f.kind = kernel::FeedbackKind::manual_offsets;
  }
  return f;
}

void take_feedback(const kernel::Feedback& f, Planner& planner, nc::Decoder& decoder) {
  if (f.kind == kernel::FeedbackKind::measured) {
    for (const auto& [name, value] : planner.take_measurement(f.measure)) (void)decoder.set_variable(name, value);
    return;
  }
  if (f.kind == kernel::FeedbackKind::stopped) {
    planner.take_stopped_position(f.path_mcs_mm);
    return;
  }
  if (f.kind == kernel::FeedbackKind::c_axis) {
    planner.take_c_axis_position(f.c_axis_deg);
    return;
  }
  for (std::size_t j = 0; j < planner.axis_count(); ++j)
    (void)decoder.set_variable("V.A.MANUAL_OFFSETS." + planner.frames().axis_name(j), f.manual_offsets_mm[j]);
}

}  // namespace nck::prep
