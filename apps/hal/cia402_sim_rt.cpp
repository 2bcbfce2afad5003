// nck_cia402_sim.so: simulated CiA 402 drives as a HAL component (loadrt
// nck_cia402_sim count=N), so that nck's CiA 402 pins can be tried and
// tested without EtherCAT hardware (lcec is not in Debian). Each instance is
// a drives::IdealDrive, the simulated machine's drive: the controlword
// steps its power state machine, and while operation is enabled it follows
// its mode exactly (position, velocity, homing: nck/drives/ideal_drive.hpp).
// Its `fault` input holds a drive fault.
//
//   nck-cia402-sim.K.controlword   u32   in   0x6040 from nck.axis.<A>.cia-controlword
//   nck-cia402-sim.K.opmode        s32   in   0x6060
//   nck-cia402-sim.K.pos-cmd       float in   0x607A target position
//   nck-cia402-sim.K.vel-cmd       float in   0x60FF target velocity
//   nck-cia402-sim.K.fault         bit   in   amplifier fault
//   nck-cia402-sim.K.statusword    u32   out  0x6041
//   nck-cia402-sim.K.opmode-display s32  out  0x6061
//   nck-cia402-sim.K.pos-fb        float out  0x6064 actual position
//   nck-cia402-sim.K.vel-fb        float out  0x606C actual velocity
// One function, nck-cia402-sim.update, steps every instance.
#include <cerrno>
#include <cstdint>
#include <new>

#include <fmt/format.h>

#include "hal.h"
#include "rtapi.h"
#include "rtapi_app.h"

#include "nck/drives/ideal_drive.hpp"

// The module parameter: how many drives (1..8).
static int count = 1;
RTAPI_MP_INT(count, "number of simulated CiA 402 drives");

namespace {

constexpr int kMaxCount = 8;

struct SimDrive {
  hal_u32_t* controlword;
  hal_s32_t* opmode;
  hal_float_t* pos_cmd;
  hal_float_t* vel_cmd;
  hal_bit_t* fault;
  hal_u32_t* statusword;
  hal_s32_t* opmode_display;
  hal_float_t* pos_fb;
  hal_float_t* vel_fb;
};

int comp_id = -1;
SimDrive* pins = nullptr;  // in HAL's shared memory (hal_malloc)
nck::drives::IdealDrive drives[kMaxCount];

void update(void*, long period_ns) {
  for (int k = 0; k < count; ++k) {
    SimDrive& p = pins[k];
    nck::drives::DriveCommand cmd;
    cmd.controlword = static_cast<std::uint16_t>(*p.controlword);
    cmd.mode_of_operation = static_cast<std::int8_t>(*p.opmode);
    cmd.target_pos = *p.pos_cmd;
    cmd.target_vel = *p.vel_cmd;
    const nck::drives::DriveFeedback& fb = drives[k].step(cmd, *p.fault, static_cast<double>(period_ns) * 1e-9);
    *p.statusword = fb.statusword;
    *p.opmode_display = fb.mode_display;
    *p.pos_fb = fb.actual_pos;
    *p.vel_fb = fb.actual_vel;
  }
}

int export_pins(int k) {
  SimDrive& p = pins[k];
  const auto name = [k](const char* pin) { return fmt::format("nck-cia402-sim.{}.{}", k, pin); };
  int r = 0;
  r |= hal_pin_u32_new(name("controlword").c_str(), HAL_IN, &p.controlword, comp_id);
  r |= hal_pin_s32_new(name("opmode").c_str(), HAL_IN, &p.opmode, comp_id);
  r |= hal_pin_float_new(name("pos-cmd").c_str(), HAL_IN, &p.pos_cmd, comp_id);
  r |= hal_pin_float_new(name("vel-cmd").c_str(), HAL_IN, &p.vel_cmd, comp_id);
  r |= hal_pin_bit_new(name("fault").c_str(), HAL_IN, &p.fault, comp_id);
  r |= hal_pin_u32_new(name("statusword").c_str(), HAL_OUT, &p.statusword, comp_id);
  r |= hal_pin_s32_new(name("opmode-display").c_str(), HAL_OUT, &p.opmode_display, comp_id);
  r |= hal_pin_float_new(name("pos-fb").c_str(), HAL_OUT, &p.pos_fb, comp_id);
  r |= hal_pin_float_new(name("vel-fb").c_str(), HAL_OUT, &p.vel_fb, comp_id);
  return r;
}

}  // namespace

extern "C" int rtapi_app_main(void) {
  if (count < 1 || count > kMaxCount) {
    rtapi_print_msg(RTAPI_MSG_ERR, "nck_cia402_sim: count=%d: 1 to %d drives\n", count, kMaxCount);
    return -EINVAL;
  }
  comp_id = hal_init("nck_cia402_sim");
  if (comp_id < 0) return comp_id;
  pins = static_cast<SimDrive*>(hal_malloc(sizeof(SimDrive) * static_cast<unsigned>(count)));
  int r = pins ? 0 : -ENOMEM;
  for (int k = 0; k < count && r == 0; ++k) r = export_pins(k);
  if (r == 0) r = hal_export_funct("nck-cia402-sim.update", update, nullptr, 1 /* floating point */, 0, comp_id);
  if (r != 0) {
    rtapi_print_msg(RTAPI_MSG_ERR, "nck_cia402_sim: the pins or the function cannot be exported\n");
    hal_exit(comp_id);
    return r;
  }
  hal_ready(comp_id);
  return 0;
}

extern "C" void rtapi_app_exit(void) { hal_exit(comp_id); }
