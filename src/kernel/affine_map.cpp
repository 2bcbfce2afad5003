#include "nck/kernel/affine_map.hpp"

namespace nck::kernel {

void AffineMap::apply(const motion::AxisVector& pcs, motion::AxisVector& mcs,
                      std::size_t n) const noexcept {
  for (std::size_t j = 0; j < n; ++j) mcs[j] = pcs[j] + shift[j];
  if (pure_translation) return;
  frames::Vec3 p{};
  for (std::size_t k = 0; k < 3; ++k) p[k] = main[k] >= 0 ? pcs[static_cast<std::size_t>(main[k])] : 0.0;
  for (std::size_t r = 0; r < 3; ++r) {
    if (main[r] < 0) continue;
    double v = shift[static_cast<std::size_t>(main[r])];
    for (std::size_t k = 0; k < 3; ++k) v += rot[r][k] * p[k];
    mcs[static_cast<std::size_t>(main[r])] = v;
  }
}

}  // namespace nck::kernel
