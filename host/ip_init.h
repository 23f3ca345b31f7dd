// ip_init.h — initialisation of the laserax IP's register map before the core is started: the
// whole register image (docs/REGISTERS.md) written through a register-write callback the caller
// supplies (its bus driver), in a fixed, documented order. Part of the host driver library
// (host/): only host/ and the standard library, C++14 (the Vitis C-simulation testbench
// tb/tb_hls_csim.cpp compiles it as C++14).
//
// Why: the HLS IP made from hls/laserax_axil.cpp has its registers as s_axilite scalar arguments,
// which have no initial value: after power-up every register reads 0, not the reset value of
// regmap/laserax_regs.csv. With zeros the configuration check fails (period, ratio, pace_m, ...
// are 0), so the core sits in the safe state with cfg_err set and counts nothing until software
// has written the whole image, not only the registers it changes. The RTL IP
// (rtl_ref/laserax_axil.v) starts at the reset values; the same call is correct for it too.
//
// Bring-up of the HLS IP:
//   1. init_registers(image, write): the image (e.g. lxt::axis_settings{}: the reset values);
//   2. start_core(write): 0x81 (ap_start | auto_restart) to the block-control word 0x00; from the
//      next clock the II = 1 pipeline takes one call per clock (the RTL IP ignores the write);
//   3. then, and only then, the writes that need a running core: a DDS table for another period
//      or amplitude (lxt::program_dds), comp_sync = 1 with compensation updates
//      (lxt::compensation_writes), error-map banks (lxt::program_map); see host/regmap.h.
#ifndef LASERAX_HOST_IP_INIT_H
#define LASERAX_HOST_IP_INIT_H

#include <cstdint>
#include <functional>
#include <string>

#include "host/regmap_table.h"

namespace lxt {

// One 32-bit write on the IP's AXI4-Lite slave (all four byte lanes): byte offset, data.
using bus_write_fn = std::function<void(uint32_t offset, uint32_t value)>;

// Block control of the HLS IP (the top's return on the s_axilite slave, bundle ctrl).
constexpr uint32_t kApCtrlOffset = 0x00;
constexpr uint32_t kApStart = 0x01;
constexpr uint32_t kApAutoRestart = 0x80;

// Writes the register image `image` through `write`, in this order:
//   1. comp_sync = 1: a core that already runs (the RTL IP after its reset, or an HLS IP being
//      initialised again) keeps its compensation pair in force while ratio and comp_offset are
//      written word by word (no torn value reaches the multiplier, DESIGN §4.7);
//   2. every other register except comp_commit, in offset order, a register wider than 32 bits
//      low word first; the reserved words are not written (they stay 0);
//   3. comp_commit = 1, comp_commit = 0: a running core loads ratio and comp_offset together;
//   4. comp_sync = 0, whatever the image holds: a core that has not run yet (the HLS IP before
//      start_core) loads its compensation pair from ratio / comp_offset in its first call only
//      with comp_sync = 0 (it cannot see the commit of step 3), so with comp_sync = 1 it would keep
//      the power-up pair, the reset ratio, instead of the image's. Set comp_sync = 1 after the
//      start (lxt::compensation_writes does it as its first write).
// init_register_writes() writes in all (36 for the current map: 1 + the 32 words of the other
// 28 registers + 2 + 1). The image is checked before the first write; false with a message
// (nothing written) when a member does not fit its register's width, or when a pulse register
// (rehome, clear, comp_commit) or a table write enable (tbl_we, map_we) is 1: an image is a
// configuration, the core acts on such a register in every clock it is 1 (a held tbl_we keeps
// the core in the safe state, a held rehome un-homed).
// Not written: the DDS table and the error-map banks (RAMs, not registers). tbl_period is written
// as the image holds it: it says which period the table RAM holds. The power-up contents are the
// table of the reset values (P = 256, amplitude 32767); for another period or amplitude write the
// image with tbl_period = 0 (safe state) and load the table after the start (lxt::program_dds
// writes tbl_period = P last).
// A core that runs while the writes land (the RTL IP) acts on each write as it lands: it may pass
// through the safe state (cfg_err) and then restarts from reset, un-homed.
bool init_registers(const axis_settings& image, const bus_write_fn& write, std::string* err = nullptr);

// The number of writes init_registers makes (for a bus budget or a testbench).
int init_register_writes();

// Starts the HLS IP: kApStart | kApAutoRestart (0x81) to kApCtrlOffset. Call it after
// init_registers. (The RTL IP has no block control: its slave ignores writes to 0x00..0x0F.)
void start_core(const bus_write_fn& write);

}  // namespace lxt

#endif  // LASERAX_HOST_IP_INIT_H
