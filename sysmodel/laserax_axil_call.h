// laserax_axil_call.h — the synthesis top laserax_axil() behind a model of the HLS IP's
// s_axilite slave, for C simulation (testbench glue): the registers are 32-bit words at their
// offsets of docs/REGISTERS.md, all 0 at power-up as in the IP Vitis HLS makes (an s_axilite
// argument has no initial value), written one bus word at a time (host/ip_init.h writes the whole
// image), and every clock calls the top with the arguments the words hold. Header-only and built
// on hls/ and the standard library only, so it compiles in the Vitis C simulation too.
//
// GENERATED FILE - do not edit. Source: regmap/laserax_regs.csv. Command: /usr/bin/python3 scripts/gen_regmap.py
#ifndef LASERAX_SYSMODEL_LASERAX_AXIL_CALL_H
#define LASERAX_SYSMODEL_LASERAX_AXIL_CALL_H

#include <cstdint>

#include "hls/laserax_axil.h"

namespace lxt {

// The HLS IP's s_axilite slave (bundle ctrl) and its block control, as the C simulation sees
// them. A register word holds the bits of its register only (the bits above the width dropped,
// as the Vitis slave keeps W bits; a register wider than 32 bits takes consecutive words, low
// word first); the block-control word 0x00 keeps ap_start (bit 0) and auto_restart (bit 7). The
// model knows only the free-running mode the IP is used in: the core runs (one call of
// laserax_axil() per clock()) while 0x00 holds 0x81, i.e. from lxt::start_core on; a write of 0 to
// 0x00 stops it after the current call. The state of the core (the static laserax_top of
// hls/laserax_axil.cpp) is kept while it is stopped. Writes to 0x04..0x0F, to the reserved word
// after each register and past the map are ignored.
class laserax_axil_slave {
public:
    // One bus write (all four byte lanes); false when the word is ignored.
    bool write(uint32_t offset, uint32_t value) {
        if (offset == 0x00) {
            ctrl_ = value & 0x81u;
            return true;
        }
        const uint32_t m = mask(offset);
        if (m == 0) return false;
        w_[(offset - 0x10u) / 4] = value & m;
        return true;
    }
    // The word a register holds (0x00: the block control; 0 for every other offset).
    uint32_t word(uint32_t offset) const {
        if (offset == 0x00) return ctrl_;
        return mask(offset) != 0 ? at(offset) : 0u;
    }
    bool running() const { return ctrl_ == 0x81u; }

    // One clock: while the core runs, one call of laserax_axil() on the registers the words hold
    // (true, outputs in out); else no call (false, out unchanged).
    bool clock(bool a, bool b, bool sw, bool lerr, lx::axis_out& out) {
        if (!running()) return false;
        laserax_axil(a, b, sw, lerr,
                     lx::uint<13>(at(0x10)),  // period
                     lx::uint<13>(at(0x18)),  // tbl_period
                     lx::uint<37>(pair(0x20)),  // ratio
                     lx::sint<64>(pair(0x30)),  // comp_offset
                     lx::uint<8>(at(0x40)),  // glitch_n
                     lx::uint<16>(at(0x48)),  // sw_debounce
                     lx::uint<16>(at(0x50)),  // min_spacing
                     lx::uint<16>(at(0x58)),  // pace_m
                     lx::uint<32>(at(0x60)),  // backlog_thr
                     lx::uint<13>(at(0x68)),  // mark_len
                     lx::uint<5>(at(0x70)),  // dac_width
                     lx::uint<18>(at(0x78)),  // amplitude
                     at(0x80) != 0,  // rehome
                     at(0x88) != 0,  // clear
                     at(0x90) != 0,  // tbl_we
                     lx::uint<10>(at(0x98)),  // tbl_addr
                     lx::uint<17>(at(0xA0)),  // tbl_data
                     at(0xA8) != 0,  // map_en
                     at(0xB0) != 0,  // bank_sel
                     lx::sint<38>(pair(0xC0)),  // map_origin0
                     lx::uint<5>(at(0xD0)),  // map_k0
                     lx::uint<11>(at(0xD8)),  // map_n0
                     lx::sint<38>(pair(0xE0)),  // map_origin1
                     lx::uint<5>(at(0xF0)),  // map_k1
                     lx::uint<11>(at(0xF8)),  // map_n1
                     at(0x100) != 0,  // map_we
                     lx::uint<10>(at(0x108)),  // map_addr
                     lx::sint<24>(at(0x110)),  // map_data
                     at(0x118) != 0,  // comp_sync
                     at(0x120) != 0,  // comp_commit
                     lx::uint<4>(at(0x128)),  // pin_cfg
                     out);
        return true;
    }

private:
    // the bits a register word holds; 0 for a word that is not a register word
    static uint32_t mask(uint32_t offset) {
        switch (offset) {
            case 0x10: return 0x1FFFu;  // period
            case 0x18: return 0x1FFFu;  // tbl_period
            case 0x20: return 0xFFFFFFFFu;  // ratio bits 31..0
            case 0x24: return 0x1Fu;  // ratio bits 36..32
            case 0x30: return 0xFFFFFFFFu;  // comp_offset bits 31..0
            case 0x34: return 0xFFFFFFFFu;  // comp_offset bits 63..32
            case 0x40: return 0xFFu;  // glitch_n
            case 0x48: return 0xFFFFu;  // sw_debounce
            case 0x50: return 0xFFFFu;  // min_spacing
            case 0x58: return 0xFFFFu;  // pace_m
            case 0x60: return 0xFFFFFFFFu;  // backlog_thr
            case 0x68: return 0x1FFFu;  // mark_len
            case 0x70: return 0x1Fu;  // dac_width
            case 0x78: return 0x3FFFFu;  // amplitude
            case 0x80: return 0x1u;  // rehome
            case 0x88: return 0x1u;  // clear
            case 0x90: return 0x1u;  // tbl_we
            case 0x98: return 0x3FFu;  // tbl_addr
            case 0xA0: return 0x1FFFFu;  // tbl_data
            case 0xA8: return 0x1u;  // map_en
            case 0xB0: return 0x1u;  // bank_sel
            case 0xC0: return 0xFFFFFFFFu;  // map_origin0 bits 31..0
            case 0xC4: return 0x3Fu;  // map_origin0 bits 37..32
            case 0xD0: return 0x1Fu;  // map_k0
            case 0xD8: return 0x7FFu;  // map_n0
            case 0xE0: return 0xFFFFFFFFu;  // map_origin1 bits 31..0
            case 0xE4: return 0x3Fu;  // map_origin1 bits 37..32
            case 0xF0: return 0x1Fu;  // map_k1
            case 0xF8: return 0x7FFu;  // map_n1
            case 0x100: return 0x1u;  // map_we
            case 0x108: return 0x3FFu;  // map_addr
            case 0x110: return 0xFFFFFFu;  // map_data
            case 0x118: return 0x1u;  // comp_sync
            case 0x120: return 0x1u;  // comp_commit
            case 0x128: return 0xFu;  // pin_cfg
            default: return 0u;
        }
    }
    uint32_t at(uint32_t offset) const { return w_[(offset - 0x10u) / 4]; }
    uint64_t pair(uint32_t offset) const { return (uint64_t(at(offset + 4)) << 32) | at(offset); }

    uint32_t w_[(0x130u - 0x10u) / 4] = {};  // the words 0x10 .. 0x12C, 0 at power-up
    uint32_t ctrl_ = 0;                    // block control: stopped at power-up
};

}  // namespace lxt

#endif  // LASERAX_SYSMODEL_LASERAX_AXIL_CALL_H
