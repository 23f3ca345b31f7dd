// laserax_regmap.h — the s_axilite register map (docs/REGISTERS.md) as compile-time constants,
// for firmware authors and static checks, plus static_asserts that every register has the width
// and signedness of its member in lx::axis_regs.
//
// GENERATED FILE - do not edit. Source: regmap/laserax_regs.csv. Command: /usr/bin/python3 scripts/gen_regmap.py
#ifndef LASERAX_HLS_LASERAX_REGMAP_H
#define LASERAX_HLS_LASERAX_REGMAP_H

#include <type_traits>

#include "hls/laserax_top.h"

namespace lx {
namespace regmap {

constexpr unsigned FIRST_OFFSET = 0x10;  // first register
constexpr unsigned END_OFFSET = 0x130;    // one past the last word (the last reserved word)
constexpr int N_REGS = 31;

// period: 0x10, 13 bits unsigned, rw, reset 256
constexpr unsigned PERIOD_OFFSET = 0x10;
constexpr int PERIOD_WIDTH = 13;
constexpr int PERIOD_WORDS = 1;
constexpr bool PERIOD_SIGNED = false;
constexpr long long PERIOD_RESET = 256LL;
// tbl_period: 0x18, 13 bits unsigned, rw, reset 256
constexpr unsigned TBL_PERIOD_OFFSET = 0x18;
constexpr int TBL_PERIOD_WIDTH = 13;
constexpr int TBL_PERIOD_WORDS = 1;
constexpr bool TBL_PERIOD_SIGNED = false;
constexpr long long TBL_PERIOD_RESET = 256LL;
// ratio: 0x20, 37 bits unsigned, rw, reset 34789620252
constexpr unsigned RATIO_OFFSET = 0x20;
constexpr int RATIO_WIDTH = 37;
constexpr int RATIO_WORDS = 2;
constexpr bool RATIO_SIGNED = false;
constexpr long long RATIO_RESET = 34789620252LL;
// comp_offset: 0x30, 64 bits signed, rw, reset 0
constexpr unsigned COMP_OFFSET_OFFSET = 0x30;
constexpr int COMP_OFFSET_WIDTH = 64;
constexpr int COMP_OFFSET_WORDS = 2;
constexpr bool COMP_OFFSET_SIGNED = true;
constexpr long long COMP_OFFSET_RESET = 0LL;
// glitch_n: 0x40, 8 bits unsigned, rw, reset 2
constexpr unsigned GLITCH_N_OFFSET = 0x40;
constexpr int GLITCH_N_WIDTH = 8;
constexpr int GLITCH_N_WORDS = 1;
constexpr bool GLITCH_N_SIGNED = false;
constexpr long long GLITCH_N_RESET = 2LL;
// sw_debounce: 0x48, 16 bits unsigned, rw, reset 16
constexpr unsigned SW_DEBOUNCE_OFFSET = 0x48;
constexpr int SW_DEBOUNCE_WIDTH = 16;
constexpr int SW_DEBOUNCE_WORDS = 1;
constexpr bool SW_DEBOUNCE_SIGNED = false;
constexpr long long SW_DEBOUNCE_RESET = 16LL;
// min_spacing: 0x50, 16 bits unsigned, rw, reset 8
constexpr unsigned MIN_SPACING_OFFSET = 0x50;
constexpr int MIN_SPACING_WIDTH = 16;
constexpr int MIN_SPACING_WORDS = 1;
constexpr bool MIN_SPACING_SIGNED = false;
constexpr long long MIN_SPACING_RESET = 8LL;
// pace_m: 0x58, 16 bits unsigned, rw, reset 61
constexpr unsigned PACE_M_OFFSET = 0x58;
constexpr int PACE_M_WIDTH = 16;
constexpr int PACE_M_WORDS = 1;
constexpr bool PACE_M_SIGNED = false;
constexpr long long PACE_M_RESET = 61LL;
// backlog_thr: 0x60, 32 bits unsigned, rw, reset 4096
constexpr unsigned BACKLOG_THR_OFFSET = 0x60;
constexpr int BACKLOG_THR_WIDTH = 32;
constexpr int BACKLOG_THR_WORDS = 1;
constexpr bool BACKLOG_THR_SIGNED = false;
constexpr long long BACKLOG_THR_RESET = 4096LL;
// mark_len: 0x68, 13 bits unsigned, rw, reset 64
constexpr unsigned MARK_LEN_OFFSET = 0x68;
constexpr int MARK_LEN_WIDTH = 13;
constexpr int MARK_LEN_WORDS = 1;
constexpr bool MARK_LEN_SIGNED = false;
constexpr long long MARK_LEN_RESET = 64LL;
// dac_width: 0x70, 5 bits unsigned, rw, reset 16
constexpr unsigned DAC_WIDTH_OFFSET = 0x70;
constexpr int DAC_WIDTH_WIDTH = 5;
constexpr int DAC_WIDTH_WORDS = 1;
constexpr bool DAC_WIDTH_SIGNED = false;
constexpr long long DAC_WIDTH_RESET = 16LL;
// amplitude: 0x78, 18 bits unsigned, rw, reset 32767
constexpr unsigned AMPLITUDE_OFFSET = 0x78;
constexpr int AMPLITUDE_WIDTH = 18;
constexpr int AMPLITUDE_WORDS = 1;
constexpr bool AMPLITUDE_SIGNED = false;
constexpr long long AMPLITUDE_RESET = 32767LL;
// rehome: 0x80, 1 bit unsigned, pulse, reset 0
constexpr unsigned REHOME_OFFSET = 0x80;
constexpr int REHOME_WIDTH = 1;
constexpr int REHOME_WORDS = 1;
constexpr bool REHOME_SIGNED = false;
constexpr long long REHOME_RESET = 0LL;
// clear: 0x88, 1 bit unsigned, pulse, reset 0
constexpr unsigned CLEAR_OFFSET = 0x88;
constexpr int CLEAR_WIDTH = 1;
constexpr int CLEAR_WORDS = 1;
constexpr bool CLEAR_SIGNED = false;
constexpr long long CLEAR_RESET = 0LL;
// tbl_we: 0x90, 1 bit unsigned, port, reset 0
constexpr unsigned TBL_WE_OFFSET = 0x90;
constexpr int TBL_WE_WIDTH = 1;
constexpr int TBL_WE_WORDS = 1;
constexpr bool TBL_WE_SIGNED = false;
constexpr long long TBL_WE_RESET = 0LL;
// tbl_addr: 0x98, 10 bits unsigned, port, reset 0
constexpr unsigned TBL_ADDR_OFFSET = 0x98;
constexpr int TBL_ADDR_WIDTH = 10;
constexpr int TBL_ADDR_WORDS = 1;
constexpr bool TBL_ADDR_SIGNED = false;
constexpr long long TBL_ADDR_RESET = 0LL;
// tbl_data: 0xA0, 17 bits unsigned, port, reset 0
constexpr unsigned TBL_DATA_OFFSET = 0xA0;
constexpr int TBL_DATA_WIDTH = 17;
constexpr int TBL_DATA_WORDS = 1;
constexpr bool TBL_DATA_SIGNED = false;
constexpr long long TBL_DATA_RESET = 0LL;
// map_en: 0xA8, 1 bit unsigned, rw, reset 0
constexpr unsigned MAP_EN_OFFSET = 0xA8;
constexpr int MAP_EN_WIDTH = 1;
constexpr int MAP_EN_WORDS = 1;
constexpr bool MAP_EN_SIGNED = false;
constexpr long long MAP_EN_RESET = 0LL;
// bank_sel: 0xB0, 1 bit unsigned, rw, reset 0
constexpr unsigned BANK_SEL_OFFSET = 0xB0;
constexpr int BANK_SEL_WIDTH = 1;
constexpr int BANK_SEL_WORDS = 1;
constexpr bool BANK_SEL_SIGNED = false;
constexpr long long BANK_SEL_RESET = 0LL;
// map_origin0: 0xC0, 38 bits signed, rw, reset 0
constexpr unsigned MAP_ORIGIN0_OFFSET = 0xC0;
constexpr int MAP_ORIGIN0_WIDTH = 38;
constexpr int MAP_ORIGIN0_WORDS = 2;
constexpr bool MAP_ORIGIN0_SIGNED = true;
constexpr long long MAP_ORIGIN0_RESET = 0LL;
// map_k0: 0xD0, 5 bits unsigned, rw, reset 10
constexpr unsigned MAP_K0_OFFSET = 0xD0;
constexpr int MAP_K0_WIDTH = 5;
constexpr int MAP_K0_WORDS = 1;
constexpr bool MAP_K0_SIGNED = false;
constexpr long long MAP_K0_RESET = 10LL;
// map_n0: 0xD8, 11 bits unsigned, rw, reset 1024
constexpr unsigned MAP_N0_OFFSET = 0xD8;
constexpr int MAP_N0_WIDTH = 11;
constexpr int MAP_N0_WORDS = 1;
constexpr bool MAP_N0_SIGNED = false;
constexpr long long MAP_N0_RESET = 1024LL;
// map_origin1: 0xE0, 38 bits signed, rw, reset 0
constexpr unsigned MAP_ORIGIN1_OFFSET = 0xE0;
constexpr int MAP_ORIGIN1_WIDTH = 38;
constexpr int MAP_ORIGIN1_WORDS = 2;
constexpr bool MAP_ORIGIN1_SIGNED = true;
constexpr long long MAP_ORIGIN1_RESET = 0LL;
// map_k1: 0xF0, 5 bits unsigned, rw, reset 10
constexpr unsigned MAP_K1_OFFSET = 0xF0;
constexpr int MAP_K1_WIDTH = 5;
constexpr int MAP_K1_WORDS = 1;
constexpr bool MAP_K1_SIGNED = false;
constexpr long long MAP_K1_RESET = 10LL;
// map_n1: 0xF8, 11 bits unsigned, rw, reset 1024
constexpr unsigned MAP_N1_OFFSET = 0xF8;
constexpr int MAP_N1_WIDTH = 11;
constexpr int MAP_N1_WORDS = 1;
constexpr bool MAP_N1_SIGNED = false;
constexpr long long MAP_N1_RESET = 1024LL;
// map_we: 0x100, 1 bit unsigned, port, reset 0
constexpr unsigned MAP_WE_OFFSET = 0x100;
constexpr int MAP_WE_WIDTH = 1;
constexpr int MAP_WE_WORDS = 1;
constexpr bool MAP_WE_SIGNED = false;
constexpr long long MAP_WE_RESET = 0LL;
// map_addr: 0x108, 10 bits unsigned, port, reset 0
constexpr unsigned MAP_ADDR_OFFSET = 0x108;
constexpr int MAP_ADDR_WIDTH = 10;
constexpr int MAP_ADDR_WORDS = 1;
constexpr bool MAP_ADDR_SIGNED = false;
constexpr long long MAP_ADDR_RESET = 0LL;
// map_data: 0x110, 24 bits signed, port, reset 0
constexpr unsigned MAP_DATA_OFFSET = 0x110;
constexpr int MAP_DATA_WIDTH = 24;
constexpr int MAP_DATA_WORDS = 1;
constexpr bool MAP_DATA_SIGNED = true;
constexpr long long MAP_DATA_RESET = 0LL;
// comp_sync: 0x118, 1 bit unsigned, rw, reset 0
constexpr unsigned COMP_SYNC_OFFSET = 0x118;
constexpr int COMP_SYNC_WIDTH = 1;
constexpr int COMP_SYNC_WORDS = 1;
constexpr bool COMP_SYNC_SIGNED = false;
constexpr long long COMP_SYNC_RESET = 0LL;
// comp_commit: 0x120, 1 bit unsigned, pulse, reset 0
constexpr unsigned COMP_COMMIT_OFFSET = 0x120;
constexpr int COMP_COMMIT_WIDTH = 1;
constexpr int COMP_COMMIT_WORDS = 1;
constexpr bool COMP_COMMIT_SIGNED = false;
constexpr long long COMP_COMMIT_RESET = 0LL;
// pin_cfg: 0x128, 4 bits unsigned, rw, reset 8
constexpr unsigned PIN_CFG_OFFSET = 0x128;
constexpr int PIN_CFG_WIDTH = 4;
constexpr int PIN_CFG_WORDS = 1;
constexpr bool PIN_CFG_SIGNED = false;
constexpr long long PIN_CFG_RESET = 8LL;

// Width and signedness of a member type: lx::sint<W> / lx::uint<W> on both back ends (own classes
// and ap_int), bool = 1 bit unsigned; is_lx is false for any other type.
template <typename T>
struct member_bits {
    static constexpr int width = T::width;
    static constexpr bool is_signed = std::is_same<T, sint<T::width> >::value;
    static constexpr bool is_lx = is_signed || std::is_same<T, uint<T::width> >::value;
};
template <>
struct member_bits<bool> {
    static constexpr int width = 1;
    static constexpr bool is_signed = false;
    static constexpr bool is_lx = true;
};
template <typename T>
constexpr bool member_is(int width, bool is_signed) {
    return member_bits<T>::is_lx && member_bits<T>::width == width && member_bits<T>::is_signed == is_signed;
}

// The declared type of a member path of axis_regs (unevaluated).
#define LX_REGMAP_MEMBER(path) std::decay<decltype(static_cast<axis_regs*>(nullptr)->path)>::type
static_assert(member_is<LX_REGMAP_MEMBER(period)>(PERIOD_WIDTH, PERIOD_SIGNED),
              "lx::axis_regs::period is not lx::uint<13> (register period)");
static_assert(member_is<LX_REGMAP_MEMBER(tbl_period)>(TBL_PERIOD_WIDTH, TBL_PERIOD_SIGNED),
              "lx::axis_regs::tbl_period is not lx::uint<13> (register tbl_period)");
static_assert(member_is<LX_REGMAP_MEMBER(ratio)>(RATIO_WIDTH, RATIO_SIGNED),
              "lx::axis_regs::ratio is not lx::uint<37> (register ratio)");
static_assert(member_is<LX_REGMAP_MEMBER(comp_offset)>(COMP_OFFSET_WIDTH, COMP_OFFSET_SIGNED),
              "lx::axis_regs::comp_offset is not lx::sint<64> (register comp_offset)");
static_assert(member_is<LX_REGMAP_MEMBER(glitch_n)>(GLITCH_N_WIDTH, GLITCH_N_SIGNED),
              "lx::axis_regs::glitch_n is not lx::uint<8> (register glitch_n)");
static_assert(member_is<LX_REGMAP_MEMBER(sw_debounce)>(SW_DEBOUNCE_WIDTH, SW_DEBOUNCE_SIGNED),
              "lx::axis_regs::sw_debounce is not lx::uint<16> (register sw_debounce)");
static_assert(member_is<LX_REGMAP_MEMBER(min_spacing)>(MIN_SPACING_WIDTH, MIN_SPACING_SIGNED),
              "lx::axis_regs::min_spacing is not lx::uint<16> (register min_spacing)");
static_assert(member_is<LX_REGMAP_MEMBER(pace_m)>(PACE_M_WIDTH, PACE_M_SIGNED),
              "lx::axis_regs::pace_m is not lx::uint<16> (register pace_m)");
static_assert(member_is<LX_REGMAP_MEMBER(backlog_thr)>(BACKLOG_THR_WIDTH, BACKLOG_THR_SIGNED),
              "lx::axis_regs::backlog_thr is not lx::uint<32> (register backlog_thr)");
static_assert(member_is<LX_REGMAP_MEMBER(mark_len)>(MARK_LEN_WIDTH, MARK_LEN_SIGNED),
              "lx::axis_regs::mark_len is not lx::uint<13> (register mark_len)");
static_assert(member_is<LX_REGMAP_MEMBER(dac_width)>(DAC_WIDTH_WIDTH, DAC_WIDTH_SIGNED),
              "lx::axis_regs::dac_width is not lx::uint<5> (register dac_width)");
static_assert(member_is<LX_REGMAP_MEMBER(amplitude)>(AMPLITUDE_WIDTH, AMPLITUDE_SIGNED),
              "lx::axis_regs::amplitude is not lx::uint<18> (register amplitude)");
static_assert(member_is<LX_REGMAP_MEMBER(rehome)>(REHOME_WIDTH, REHOME_SIGNED),
              "lx::axis_regs::rehome is not bool (register rehome)");
static_assert(member_is<LX_REGMAP_MEMBER(clear)>(CLEAR_WIDTH, CLEAR_SIGNED),
              "lx::axis_regs::clear is not bool (register clear)");
static_assert(member_is<LX_REGMAP_MEMBER(tbl_we)>(TBL_WE_WIDTH, TBL_WE_SIGNED),
              "lx::axis_regs::tbl_we is not bool (register tbl_we)");
static_assert(member_is<LX_REGMAP_MEMBER(tbl_addr)>(TBL_ADDR_WIDTH, TBL_ADDR_SIGNED),
              "lx::axis_regs::tbl_addr is not lx::uint<10> (register tbl_addr)");
static_assert(member_is<LX_REGMAP_MEMBER(tbl_data)>(TBL_DATA_WIDTH, TBL_DATA_SIGNED),
              "lx::axis_regs::tbl_data is not lx::uint<17> (register tbl_data)");
static_assert(member_is<LX_REGMAP_MEMBER(emap.map_en)>(MAP_EN_WIDTH, MAP_EN_SIGNED),
              "lx::axis_regs::emap.map_en is not bool (register map_en)");
static_assert(member_is<LX_REGMAP_MEMBER(emap.bank_sel)>(BANK_SEL_WIDTH, BANK_SEL_SIGNED),
              "lx::axis_regs::emap.bank_sel is not bool (register bank_sel)");
static_assert(member_is<LX_REGMAP_MEMBER(emap.geom[0].origin)>(MAP_ORIGIN0_WIDTH, MAP_ORIGIN0_SIGNED),
              "lx::axis_regs::emap.geom[0].origin is not lx::sint<38> (register map_origin0)");
static_assert(member_is<LX_REGMAP_MEMBER(emap.geom[0].spacing_log2)>(MAP_K0_WIDTH, MAP_K0_SIGNED),
              "lx::axis_regs::emap.geom[0].spacing_log2 is not lx::uint<5> (register map_k0)");
static_assert(member_is<LX_REGMAP_MEMBER(emap.geom[0].n_points)>(MAP_N0_WIDTH, MAP_N0_SIGNED),
              "lx::axis_regs::emap.geom[0].n_points is not lx::uint<11> (register map_n0)");
static_assert(member_is<LX_REGMAP_MEMBER(emap.geom[1].origin)>(MAP_ORIGIN1_WIDTH, MAP_ORIGIN1_SIGNED),
              "lx::axis_regs::emap.geom[1].origin is not lx::sint<38> (register map_origin1)");
static_assert(member_is<LX_REGMAP_MEMBER(emap.geom[1].spacing_log2)>(MAP_K1_WIDTH, MAP_K1_SIGNED),
              "lx::axis_regs::emap.geom[1].spacing_log2 is not lx::uint<5> (register map_k1)");
static_assert(member_is<LX_REGMAP_MEMBER(emap.geom[1].n_points)>(MAP_N1_WIDTH, MAP_N1_SIGNED),
              "lx::axis_regs::emap.geom[1].n_points is not lx::uint<11> (register map_n1)");
static_assert(member_is<LX_REGMAP_MEMBER(emap.we)>(MAP_WE_WIDTH, MAP_WE_SIGNED),
              "lx::axis_regs::emap.we is not bool (register map_we)");
static_assert(member_is<LX_REGMAP_MEMBER(emap.addr)>(MAP_ADDR_WIDTH, MAP_ADDR_SIGNED),
              "lx::axis_regs::emap.addr is not lx::uint<10> (register map_addr)");
static_assert(member_is<LX_REGMAP_MEMBER(emap.data)>(MAP_DATA_WIDTH, MAP_DATA_SIGNED),
              "lx::axis_regs::emap.data is not lx::sint<24> (register map_data)");
static_assert(member_is<LX_REGMAP_MEMBER(comp_sync)>(COMP_SYNC_WIDTH, COMP_SYNC_SIGNED),
              "lx::axis_regs::comp_sync is not bool (register comp_sync)");
static_assert(member_is<LX_REGMAP_MEMBER(comp_commit)>(COMP_COMMIT_WIDTH, COMP_COMMIT_SIGNED),
              "lx::axis_regs::comp_commit is not bool (register comp_commit)");
static_assert(member_is<LX_REGMAP_MEMBER(pin_cfg)>(PIN_CFG_WIDTH, PIN_CFG_SIGNED),
              "lx::axis_regs::pin_cfg is not lx::uint<4> (register pin_cfg)");
#undef LX_REGMAP_MEMBER

}  // namespace regmap
}  // namespace lx

#endif  // LASERAX_HLS_LASERAX_REGMAP_H
