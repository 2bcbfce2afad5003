// nck.so: the real-time HAL component (loadrt nck). It holds the kernel only:
// its load function attaches the segment nck-hal created, builds the kernel
// from the machine packed there and exports the pins and one function,
// nck.cycle, which runs one Kernel::tick() per call (apps/hal/cycle.cpp).
// No decoder, no file access, no server here: rtapi_app runs as root.
#include <new>
#include <string>

#include <fmt/format.h>

#include "hal.h"
#include "rtapi.h"
#include "rtapi_app.h"

#include "hal/cycle.hpp"

namespace {

int comp_id = -1;
int shmem_id = -1;
nck::hal::Cycle* cycle = nullptr;


// HAL keeps each pin's value pointer in its shared memory (hal_malloc) and
// re-points it when the pin is netted; the cycle follows it every time.
int bit(hal_pin_dir_t d, volatile bool**& to, const std::string& name) {
  auto** p = static_cast<hal_bit_t**>(hal_malloc(sizeof(hal_bit_t*)));
  if (!p) return -ENOMEM;
  int r = hal_pin_bit_new(name.c_str(), d, p, comp_id);
  to = p;
  return r;
}
int flt(hal_pin_dir_t d, volatile double**& to, const std::string& name) {
  auto** p = static_cast<hal_float_t**>(hal_malloc(sizeof(hal_float_t*)));
  if (!p) return -ENOMEM;
  int r = hal_pin_float_new(name.c_str(), d, p, comp_id);
  to = p;
  return r;
}
int u32(hal_pin_dir_t d, volatile std::uint32_t**& to, const std::string& name) {
  auto** p = static_cast<hal_u32_t**>(hal_malloc(sizeof(hal_u32_t*)));
  if (!p) return -ENOMEM;
  int r = hal_pin_u32_new(name.c_str(), d, p, comp_id);
  to = p;
  return r;
}
int s32(hal_pin_dir_t d, volatile std::int32_t**& to, const std::string& name) {
  auto** p = static_cast<hal_s32_t**>(hal_malloc(sizeof(hal_s32_t*)));
  if (!p) return -ENOMEM;
  int r = hal_pin_s32_new(name.c_str(), d, p, comp_id);
  to = p;
  return r;
}

// A CiA 402 drive's words and velocities, named after its axis or spindle `n`.
int cia_pins(nck::hal::CiaPins& cia, const std::string& n) {
  int r = 0;
  r |= u32(HAL_OUT, cia.controlword, n + ".cia-controlword");
  r |= s32(HAL_OUT, cia.opmode, n + ".cia-opmode");
  r |= flt(HAL_OUT, cia.vel_cmd, n + ".vel-cmd");
  r |= u32(HAL_IN, cia.statusword, n + ".cia-statusword");
  r |= s32(HAL_IN, cia.opmode_display, n + ".cia-opmode-display");
  r |= flt(HAL_IN, cia.vel_fb, n + ".vel-fb");
  return r;
}

int make_pins(nck::hal::Cycle& c) {
  int r = 0;
  nck::hal::MachinePins& m = c.machine_pins;
  r |= bit(HAL_IN, m.estop, "nck.estop");
  r |= bit(HAL_IN, m.machine_on, "nck.machine-on");
  r |= bit(HAL_OUT, m.watchdog, "nck.watchdog");
  r |= bit(HAL_OUT, m.error, "nck.error");
  r |= u32(HAL_OUT, m.error_id, "nck.error-id");
  r |= u32(HAL_OUT, m.cycles, "nck.cycles");
  r |= s32(HAL_OUT, m.tick_time, "nck.tick-time");
  r |= flt(HAL_OUT, m.clocks_per_us, "nck.clocks-per-us");
  for (const auto& a : c.axes()) {
    nck::hal::AxisPins p{};
    const std::string n = a.channel == 0 ? fmt::format("nck.axis.{}", a.name)
                                         : fmt::format("nck.axis.{}.{}", a.channel + 1, a.name);
    r |= flt(HAL_OUT, p.pos_cmd, n + ".pos-cmd");
    r |= flt(HAL_IN, p.pos_fb, n + ".pos-fb");
    r |= flt(HAL_OUT, p.following_error, n + ".f-error");
    r |= bit(HAL_OUT, p.enable, n + ".enable");
    r |= bit(HAL_IN, p.amp_fault, n + ".amp-fault-in");
    r |= bit(HAL_IN, p.home_sw, n + ".home-sw-in");
    r |= bit(HAL_IN, p.limit_pos, n + ".pos-lim-sw-in");
    r |= bit(HAL_IN, p.limit_neg, n + ".neg-lim-sw-in");
    r |= bit(HAL_OUT, p.homed, n + ".homed");
    c.axis_pins.push_back(p);
    nck::hal::CiaPins cia{};
    if (a.cia402) r |= cia_pins(cia, n);  // a CiA 402 drive: its words
    else if (a.drive >= 0) r |= flt(HAL_OUT, cia.vel_cmd, n + ".vel-cmd");  // a conventional drive's set point
    c.cia_pins.push_back(cia);
  }
  for (std::size_t ch = 0; ch < c.channel_count(); ++ch) {
    nck::hal::ChannelPins p{};
    const std::string n = fmt::format("nck.channel.{}", ch + 1);
    r |= bit(HAL_IN, p.cycle_start, n + ".cycle-start");
    r |= bit(HAL_IN, p.feedhold, n + ".feedhold");
    r |= bit(HAL_IN, p.reset, n + ".reset");
    r |= bit(HAL_IN, p.single_step, n + ".single-step");
    r |= bit(HAL_IN, p.optional_stop, n + ".optional-stop");
    r |= flt(HAL_IN, p.feed_override, n + ".feed-override");
    r |= flt(HAL_IN, p.rapid_override, n + ".rapid-override");
    r |= u32(HAL_IN, p.skip_mask, n + ".skip-mask");
    r |= s32(HAL_OUT, p.program_state, n + ".program-state");
    r |= s32(HAL_OUT, p.status, n + ".status");
    r |= s32(HAL_OUT, p.block_line, n + ".block-line");
    r |= flt(HAL_OUT, p.path_velocity, n + ".path-velocity");
    r |= bit(HAL_OUT, p.done, n + ".done");
    if (r == 0) {
      **p.feed_override = 100.0;
      **p.rapid_override = 100.0;
    }  // an unconnected input keeps its value
    c.channel_pins.push_back(p);
  }
  for (std::size_t s = 0; s < c.spindle_count(); ++s) {
    nck::hal::SpindlePins p{};
    const std::string n = fmt::format("nck.spindle.{}", c.spindle_name(s));
    r |= flt(HAL_OUT, p.speed_cmd_rpm, n + ".speed-cmd-rpm");
    r |= flt(HAL_OUT, p.pos_cmd_deg, n + ".pos-cmd-deg");
    r |= bit(HAL_OUT, p.at_speed, n + ".at-speed");
    r |= bit(HAL_OUT, p.orient, n + ".orient");
    r |= flt(HAL_IN, p.speed_in_rpm, n + ".speed-in");
    r |= flt(HAL_IN, p.revolutions, n + ".revs");
    r |= bit(HAL_IN, p.feedback_valid, n + ".feedback-valid");
    r |= bit(HAL_OUT, p.homed, n + ".homed");
    r |= bit(HAL_IO, p.index_enable, n + ".index-enable");
    if (r == 0) p.unwired = *p.index_enable;  // not netted yet: HAL's own storage of the pin
    r |= flt(HAL_IN, p.override_pct, n + ".override");
    r |= bit(HAL_IN, p.feedhold, n + ".feedhold");
    r |= bit(HAL_IN, p.stop_at_end, n + ".stop-at-end");
    r |= bit(HAL_IN, p.reset, n + ".reset");
    if (r == 0) **p.override_pct = 100.0;  // an unconnected input keeps its value
    p.axis_list = c.spindle_axis_list(s);
    if (p.axis_list >= 0) r |= bit(HAL_IN, p.amp_fault, n + ".amp-fault-in");
    c.spindle_pins.push_back(p);
    nck::hal::SpindleDrivePins d{};
    const nck::config::AxisConfig* ax = p.axis_list >= 0 ? &c.machine().axes[static_cast<std::size_t>(p.axis_list)] : nullptr;
    if (ax && (ax->is_cia402() || ax->is_conventional())) d.drive = p.axis_list;
    d.cia402 = ax && ax->is_cia402();
    if (d.cia402) {  // a CiA 402 drive: its words, and the drive's own positions
      r |= cia_pins(d.words, n);
      r |= flt(HAL_OUT, d.pos_cmd, n + ".drive-pos-cmd");
      r |= flt(HAL_IN, d.pos_fb, n + ".drive-pos-fb");
    } else if (d.drive >= 0) {  // a conventional drive: its velocity set point (deg/s)
      r |= flt(HAL_OUT, d.words.vel_cmd, n + ".vel-cmd");
    }
    c.spindle_drive_pins.push_back(d);
    nck::hal::PlcSpindleCommandPins k{};
    r |= s32(HAL_IN, k.m, n + ".plc-cmd-m");
    r |= flt(HAL_IN, k.rpm, n + ".plc-cmd-rpm");
    r |= flt(HAL_IN, k.pos_deg, n + ".plc-cmd-pos");
    r |= bit(HAL_IN, k.request, n + ".plc-cmd-request");
    r |= bit(HAL_OUT, k.done, n + ".plc-cmd-done");
    c.plc_command_pins.push_back(k);
  }
  for (std::size_t k = 0; k < nck::hal::kPlcSlots; ++k) {
    nck::hal::PlcPins& p = c.plc_pins[k];
    const std::string n = fmt::format("nck.plc.{}", k);
    r |= bit(HAL_OUT, p.request, n + ".request");
    r |= s32(HAL_OUT, p.kind, n + ".kind");
    r |= s32(HAL_OUT, p.number, n + ".number");
    r |= s32(HAL_OUT, p.channel, n + ".channel");
    r |= flt(HAL_OUT, p.value, n + ".value");
    r |= bit(HAL_IN, p.ack, n + ".ack");
  }
  return r;
}

void cycle_function(void* arg, long period_ns) { static_cast<nck::hal::Cycle*>(arg)->run(period_ns); }

}  // namespace

extern "C" int rtapi_app_main(void) {
  comp_id = hal_init("nck");
  if (comp_id < 0) return comp_id;
  try {
    shmem_id = rtapi_shmem_new(nck::hal::kLinkKey, comp_id, sizeof(nck::hal::Link));
    void* mem = nullptr;
    if (shmem_id < 0 || rtapi_shmem_getptr(shmem_id, &mem) != 0 || !mem) {
      rtapi_print_msg(RTAPI_MSG_ERR, "nck: %u: the shared segment cannot be attached\n",
                      static_cast<unsigned>(nck::ErrorId::HalSharedMemory));
      hal_exit(comp_id);
      return -EINVAL;
    }
    auto* link = static_cast<nck::hal::Link*>(mem);  // nck-hal constructed it
    cycle = new nck::hal::Cycle();
    std::string error;
    if (!cycle->build(*link, error)) {
      rtapi_print_msg(RTAPI_MSG_ERR, "nck: %s\n", error.c_str());
      delete cycle;
      cycle = nullptr;
      hal_exit(comp_id);
      return -EINVAL;
    }
    cycle->clocks = {rtapi_get_clocks, rtapi_get_time};
    if (make_pins(*cycle) != 0 ||
        hal_export_funct("nck.cycle", cycle_function, cycle, 1 /* uses floating point */, 0, comp_id) != 0) {
      rtapi_print_msg(RTAPI_MSG_ERR, "nck: the pins or nck.cycle cannot be exported (a name twice?)\n");
      hal_exit(comp_id);
      return -EINVAL;
    }
  } catch (const std::exception& e) {  // allocation while loading: refuse, never take rtapi_app down
    rtapi_print_msg(RTAPI_MSG_ERR, "nck: %u: loading stopped: %s\n",
                    static_cast<unsigned>(nck::ErrorId::HalMachineInvalid), e.what());
    hal_exit(comp_id);
    return -EINVAL;
  }
  hal_ready(comp_id);
  return 0;
}

extern "C" void rtapi_app_exit(void) {
  delete cycle;  // the thread no longer calls nck.cycle: HAL removed the function first
  cycle = nullptr;
  hal_exit(comp_id);
}
