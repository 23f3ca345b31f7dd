/* laserax_regs_c.h — the laserax s_axilite register map for C firmware (docs/REGISTERS.md).
 *
 * GENERATED FILE - do not edit. Source: regmap/laserax_regs.csv. Command: /usr/bin/python3 scripts/gen_regmap.py
 *
 * Byte offsets on the AXI-lite slave (bundle ctrl). A register wider than 32 bits takes WORDS
 * consecutive 32-bit words, low word first; the word after them is reserved (Vitis HLS control
 * word). Pulse registers: write 1, then 0. RESET is the value
 * (sign-extended for SIGNED registers); MIN/MAX/STEP are given where the range is restricted.
 */
#ifndef LASERAX_REGS_C_H
#define LASERAX_REGS_C_H

#define LASERAX_REG_FIRST_OFFSET 0x10u
#define LASERAX_REG_END_OFFSET 0x130u
#define LASERAX_REG_COUNT 31

/* period: sin/cos period P (20 um = 256 counts); a change while running restarts the chain (one safe-state call). Bad value: outside 8..4096, not a multiple of 8, != tbl_period or mark_len outside period/4..period -> cfg_err (safe state) */
#define LASERAX_REG_PERIOD_OFFSET 0x10u
#define LASERAX_REG_PERIOD_WIDTH 13
#define LASERAX_REG_PERIOD_WORDS 1
#define LASERAX_REG_PERIOD_SIGNED 0
#define LASERAX_REG_PERIOD_RESET 256LL
#define LASERAX_REG_PERIOD_MIN 8LL
#define LASERAX_REG_PERIOD_MAX 4096LL
#define LASERAX_REG_PERIOD_STEP 8
/* tbl_period: period the quarter-wave table was computed for; written after loading the table. Bad value: != period -> cfg_err (the safe-state window of a table load) */
#define LASERAX_REG_TBL_PERIOD_OFFSET 0x18u
#define LASERAX_REG_TBL_PERIOD_WIDTH 13
#define LASERAX_REG_TBL_PERIOD_WORDS 1
#define LASERAX_REG_TBL_PERIOD_SIGNED 0
#define LASERAX_REG_TBL_PERIOD_RESET 256LL
#define LASERAX_REG_TBL_PERIOD_MIN 8LL
#define LASERAX_REG_TBL_PERIOD_MAX 4096LL
#define LASERAX_REG_TBL_PERIOD_STEP 8
/* ratio: pulse multiplier ratio R: comp = floor((N * R + comp_offset) / 2^32); reset = rha(632.991 / 1.000271 / 78.125 * 2^32). Bad value: 0 -> cfg_err; a wrong non-zero ratio scales every position (nothing in the core can see it: host side, lxt::compensation) */
#define LASERAX_REG_RATIO_OFFSET 0x20u
#define LASERAX_REG_RATIO_WIDTH 37
#define LASERAX_REG_RATIO_WORDS 2
#define LASERAX_REG_RATIO_SIGNED 0
#define LASERAX_REG_RATIO_RESET 34789620252LL
#define LASERAX_REG_RATIO_MIN 1LL
#define LASERAX_REG_RATIO_MAX 137438953471LL
/* comp_offset: offset added to N * R in the pulse multiplier (thermal origin: rha(-K168 * K169 * 1e-5 * 2^32), 0 = none). Bad value: none (every value legal); a wrong offset shifts every position (host side) */
#define LASERAX_REG_COMP_OFFSET_OFFSET 0x30u
#define LASERAX_REG_COMP_OFFSET_WIDTH 64
#define LASERAX_REG_COMP_OFFSET_WORDS 2
#define LASERAX_REG_COMP_OFFSET_SIGNED 1
#define LASERAX_REG_COMP_OFFSET_RESET 0LL
/* glitch_n: glitch filter length N of the A/B/LERR inputs (0 and 1 = pass after one clock); shorter pulses are suppressed and set glitch_st. Bad value: N >= min_spacing puts the chain in the safe state (cfg_err), since a pulse the filter passes could then lose 4 counts silently (DESIGN 4.2) */
#define LASERAX_REG_GLITCH_N_OFFSET 0x40u
#define LASERAX_REG_GLITCH_N_WIDTH 8
#define LASERAX_REG_GLITCH_N_WORDS 1
#define LASERAX_REG_GLITCH_N_SIGNED 0
#define LASERAX_REG_GLITCH_N_RESET 2LL
#define LASERAX_REG_GLITCH_N_MIN 0LL
#define LASERAX_REG_GLITCH_N_MAX 255LL
/* sw_debounce: debounce length of the reference switch input. Bad value: none; too short lets switch bounce through (extra homing edges), too long delays homing */
#define LASERAX_REG_SW_DEBOUNCE_OFFSET 0x48u
#define LASERAX_REG_SW_DEBOUNCE_WIDTH 16
#define LASERAX_REG_SW_DEBOUNCE_WORDS 1
#define LASERAX_REG_SW_DEBOUNCE_SIGNED 0
#define LASERAX_REG_SW_DEBOUNCE_RESET 16LL
/* min_spacing: minimum spacing of counted A/B edges; closer edges set ovs_edge_st. Every filter-passing pulse shorter than 2 * min_spacing that changes the count is flagged; set it below the shortest real edge spacing (reset 8 = 80 ns at 100 MHz). Bad value: min_spacing <= max(glitch_n, 1) puts the chain in the safe state (cfg_err); too large a value flags real motion with ovs_edge_st */
#define LASERAX_REG_MIN_SPACING_OFFSET 0x50u
#define LASERAX_REG_MIN_SPACING_WIDTH 16
#define LASERAX_REG_MIN_SPACING_WORDS 1
#define LASERAX_REG_MIN_SPACING_SIGNED 0
#define LASERAX_REG_MIN_SPACING_RESET 8LL
#define LASERAX_REG_MIN_SPACING_MIN 2LL
#define LASERAX_REG_MIN_SPACING_MAX 65535LL
/* pace_m: output pacer: consecutive output counts at least M clocks apart in every stage (each qa/qb state lasts >= M clocks; real counts 2M apart in the referencing window); choose M for the controller input (docs/CONTROLLER.md). Reset 61: safe for every input of that table (a hostmot2 counter at LinuxCNC's defaults needs 61), up to 128 mm/s of output at P = 256; faster motion builds a backlog (ovs_backlog_st), never a lost count. Bad value: below 2 -> cfg_err; a large M lets the backlog grow (ovs_backlog_st above backlog_thr, never a lost count) */
#define LASERAX_REG_PACE_M_OFFSET 0x58u
#define LASERAX_REG_PACE_M_WIDTH 16
#define LASERAX_REG_PACE_M_WORDS 1
#define LASERAX_REG_PACE_M_SIGNED 0
#define LASERAX_REG_PACE_M_RESET 61LL
#define LASERAX_REG_PACE_M_MIN 2LL
#define LASERAX_REG_PACE_M_MAX 65535LL
/* backlog_thr: pacer backlog alarm threshold (|backlog| > thr sets ovs_backlog_st). Bad value: none; a large threshold delays the backlog alarm, 0 raises it at any backlog */
#define LASERAX_REG_BACKLOG_THR_OFFSET 0x60u
#define LASERAX_REG_BACKLOG_THR_WIDTH 32
#define LASERAX_REG_BACKLOG_THR_WORDS 1
#define LASERAX_REG_BACKLOG_THR_SIGNED 0
#define LASERAX_REG_BACKLOG_THR_RESET 4096LL
/* mark_len: reference mark length: the mark is active from B to C = B + mark_len. Bad value: outside period/4..period -> cfg_err */
#define LASERAX_REG_MARK_LEN_OFFSET 0x68u
#define LASERAX_REG_MARK_LEN_WIDTH 13
#define LASERAX_REG_MARK_LEN_WORDS 1
#define LASERAX_REG_MARK_LEN_SIGNED 0
#define LASERAX_REG_MARK_LEN_RESET 64LL
#define LASERAX_REG_MARK_LEN_MIN 2LL
#define LASERAX_REG_MARK_LEN_MAX 4096LL
/* dac_width: width of the sin/cos DAC codes; limits the amplitude. Bad value: outside 12..18 -> cfg_err; a table in use that does not fit (dac_width lowered without reloading the table) -> sin/cos clamped to +-(2^(dac_width-1)-1) and sticky dac_clip_st (part of alarm) */
#define LASERAX_REG_DAC_WIDTH_OFFSET 0x70u
#define LASERAX_REG_DAC_WIDTH_WIDTH 5
#define LASERAX_REG_DAC_WIDTH_WORDS 1
#define LASERAX_REG_DAC_WIDTH_SIGNED 0
#define LASERAX_REG_DAC_WIDTH_RESET 16LL
#define LASERAX_REG_DAC_WIDTH_MIN 12LL
#define LASERAX_REG_DAC_WIDTH_MAX 18LL
/* amplitude: sin/cos amplitude (the table value at a quarter period). Bad value: 0 or above 2^(dac_width-1)-1 -> cfg_err; a value that differs from the amplitude the table was computed for is not seen by the check: reload the table (lxt::program_dds); table words above the DAC range are clamped and flagged (dac_clip_st) */
#define LASERAX_REG_AMPLITUDE_OFFSET 0x78u
#define LASERAX_REG_AMPLITUDE_WIDTH 18
#define LASERAX_REG_AMPLITUDE_WORDS 1
#define LASERAX_REG_AMPLITUDE_SIGNED 0
#define LASERAX_REG_AMPLITUDE_RESET 32767LL
#define LASERAX_REG_AMPLITUDE_MIN 1LL
#define LASERAX_REG_AMPLITUDE_MAX 131071LL
/* rehome: back to stage 1 (un-homed) without a phase jump; a new switch edge homes again. Bad value: held at 1, the chain stays un-homed (stage 1) until it returns to 0 */
#define LASERAX_REG_REHOME_OFFSET 0x80u
#define LASERAX_REG_REHOME_WIDTH 1
#define LASERAX_REG_REHOME_WORDS 1
#define LASERAX_REG_REHOME_SIGNED 0
#define LASERAX_REG_REHOME_RESET 0LL
/* clear: clears the sticky flags illegal_st / ovs_edge_st / ovs_backlog_st / glitch_st / lerr_alarm and err_cnt (an event in the same clock wins). Bad value: held at 1, the flags are cleared every clock but every event still sets its flag in its own clock (never hidden) */
#define LASERAX_REG_CLEAR_OFFSET 0x88u
#define LASERAX_REG_CLEAR_WIDTH 1
#define LASERAX_REG_CLEAR_WORDS 1
#define LASERAX_REG_CLEAR_SIGNED 0
#define LASERAX_REG_CLEAR_RESET 0LL
/* tbl_we: quarter-wave table write enable: writes tbl_data to tbl_addr in every clock while 1; each such clock and the clock after it are in the safe state (cfg_err: DESIGN 4.6), so load the table while tbl_period != period. Bad value: a write while running puts that clock and the next in the safe state (cfg_err, the chain restarts un-homed); the table is never changed under a running chain without a flag */
#define LASERAX_REG_TBL_WE_OFFSET 0x90u
#define LASERAX_REG_TBL_WE_WIDTH 1
#define LASERAX_REG_TBL_WE_WORDS 1
#define LASERAX_REG_TBL_WE_SIGNED 0
#define LASERAX_REG_TBL_WE_RESET 0LL
#define LASERAX_REG_TBL_WE_MIN 0LL
#define LASERAX_REG_TBL_WE_MAX 0LL
/* tbl_addr: quarter-wave table address 0 .. P/4-1. Bad value: an address >= P/4 writes a word the current period does not read */
#define LASERAX_REG_TBL_ADDR_OFFSET 0x98u
#define LASERAX_REG_TBL_ADDR_WIDTH 10
#define LASERAX_REG_TBL_ADDR_WORDS 1
#define LASERAX_REG_TBL_ADDR_SIGNED 0
#define LASERAX_REG_TBL_ADDR_RESET 0LL
/* tbl_data: quarter-wave table word rha(amplitude * sin(2 pi k / P)). Bad value: a wrong word gives a wrong code (within the DAC range: clamped and dac_clip_st beyond it) */
#define LASERAX_REG_TBL_DATA_OFFSET 0xA0u
#define LASERAX_REG_TBL_DATA_WIDTH 17
#define LASERAX_REG_TBL_DATA_WORDS 1
#define LASERAX_REG_TBL_DATA_SIGNED 0
#define LASERAX_REG_TBL_DATA_RESET 0LL
/* map_en: error map enable (docs/ERROR_MAP.md); active only while homed and the selected bank's geometry is valid. Bad value: 1 with an invalid geometry of the selected bank -> map_cfg_err, map inactive */
#define LASERAX_REG_MAP_EN_OFFSET 0xA8u
#define LASERAX_REG_MAP_EN_WIDTH 1
#define LASERAX_REG_MAP_EN_WORDS 1
#define LASERAX_REG_MAP_EN_SIGNED 0
#define LASERAX_REG_MAP_EN_RESET 0LL
/* bank_sel: active error-map bank; the map write port writes the other bank. Bad value: selecting a bank that is not loaded applies its words (host side: load, then flip) */
#define LASERAX_REG_BANK_SEL_OFFSET 0xB0u
#define LASERAX_REG_BANK_SEL_WIDTH 1
#define LASERAX_REG_BANK_SEL_WORDS 1
#define LASERAX_REG_BANK_SEL_SIGNED 0
#define LASERAX_REG_BANK_SEL_RESET 0LL
/* map_origin0: position of table point 0 of bank 0 (comp coordinates). Bad value: none; a wrong origin shifts the correction (host side) */
#define LASERAX_REG_MAP_ORIGIN0_OFFSET 0xC0u
#define LASERAX_REG_MAP_ORIGIN0_WIDTH 38
#define LASERAX_REG_MAP_ORIGIN0_WORDS 2
#define LASERAX_REG_MAP_ORIGIN0_SIGNED 1
#define LASERAX_REG_MAP_ORIGIN0_RESET 0LL
/* map_k0: bank 0 point spacing 2^k counts (16 counts = 1.25 um .. 2^20 counts = 81.9 mm). Bad value: outside 4..20 -> map_cfg_err while map_en and bank 0 selected (map inactive) */
#define LASERAX_REG_MAP_K0_OFFSET 0xD0u
#define LASERAX_REG_MAP_K0_WIDTH 5
#define LASERAX_REG_MAP_K0_WORDS 1
#define LASERAX_REG_MAP_K0_SIGNED 0
#define LASERAX_REG_MAP_K0_RESET 10LL
#define LASERAX_REG_MAP_K0_MIN 4LL
#define LASERAX_REG_MAP_K0_MAX 20LL
/* map_n0: number of table points used in bank 0. Bad value: outside 2..1024 -> map_cfg_err while map_en and bank 0 selected (map inactive) */
#define LASERAX_REG_MAP_N0_OFFSET 0xD8u
#define LASERAX_REG_MAP_N0_WIDTH 11
#define LASERAX_REG_MAP_N0_WORDS 1
#define LASERAX_REG_MAP_N0_SIGNED 0
#define LASERAX_REG_MAP_N0_RESET 1024LL
#define LASERAX_REG_MAP_N0_MIN 2LL
#define LASERAX_REG_MAP_N0_MAX 1024LL
/* map_origin1: position of table point 0 of bank 1 (comp coordinates). Bad value: none; a wrong origin shifts the correction (host side) */
#define LASERAX_REG_MAP_ORIGIN1_OFFSET 0xE0u
#define LASERAX_REG_MAP_ORIGIN1_WIDTH 38
#define LASERAX_REG_MAP_ORIGIN1_WORDS 2
#define LASERAX_REG_MAP_ORIGIN1_SIGNED 1
#define LASERAX_REG_MAP_ORIGIN1_RESET 0LL
/* map_k1: bank 1 point spacing 2^k counts. Bad value: outside 4..20 -> map_cfg_err while map_en and bank 1 selected (map inactive) */
#define LASERAX_REG_MAP_K1_OFFSET 0xF0u
#define LASERAX_REG_MAP_K1_WIDTH 5
#define LASERAX_REG_MAP_K1_WORDS 1
#define LASERAX_REG_MAP_K1_SIGNED 0
#define LASERAX_REG_MAP_K1_RESET 10LL
#define LASERAX_REG_MAP_K1_MIN 4LL
#define LASERAX_REG_MAP_K1_MAX 20LL
/* map_n1: number of table points used in bank 1. Bad value: outside 2..1024 -> map_cfg_err while map_en and bank 1 selected (map inactive) */
#define LASERAX_REG_MAP_N1_OFFSET 0xF8u
#define LASERAX_REG_MAP_N1_WIDTH 11
#define LASERAX_REG_MAP_N1_WORDS 1
#define LASERAX_REG_MAP_N1_SIGNED 0
#define LASERAX_REG_MAP_N1_RESET 1024LL
#define LASERAX_REG_MAP_N1_MIN 2LL
#define LASERAX_REG_MAP_N1_MAX 1024LL
/* map_we: error-map table write enable: writes map_data to map_addr of bank !bank_sel in every clock while 1. Bad value: none (writes go to the bank not selected) */
#define LASERAX_REG_MAP_WE_OFFSET 0x100u
#define LASERAX_REG_MAP_WE_WIDTH 1
#define LASERAX_REG_MAP_WE_WORDS 1
#define LASERAX_REG_MAP_WE_SIGNED 0
#define LASERAX_REG_MAP_WE_RESET 0LL
/* map_addr: error-map table address 0 .. 1023. Bad value: an address >= map_n of that bank writes a word the map does not read */
#define LASERAX_REG_MAP_ADDR_OFFSET 0x108u
#define LASERAX_REG_MAP_ADDR_WIDTH 10
#define LASERAX_REG_MAP_ADDR_WORDS 1
#define LASERAX_REG_MAP_ADDR_SIGNED 0
#define LASERAX_REG_MAP_ADDR_RESET 0LL
/* map_data: error-map table word: correction at that point in 1/256 output count. Bad value: a wrong word gives a wrong correction, limited to the 17-bit corr range */
#define LASERAX_REG_MAP_DATA_OFFSET 0x110u
#define LASERAX_REG_MAP_DATA_WIDTH 24
#define LASERAX_REG_MAP_DATA_WORDS 1
#define LASERAX_REG_MAP_DATA_SIGNED 1
#define LASERAX_REG_MAP_DATA_RESET 0LL
/* comp_sync: 1: ratio and comp_offset take effect only in a clock with comp_commit = 1 (a bus host writes their words, then pulses comp_commit: no half-written value ever reaches the multiplier); 0: from the clock after they are written (register stage). Bad value: 1 without comp_commit pulses keeps the old ratio / comp_offset in force */
#define LASERAX_REG_COMP_SYNC_OFFSET 0x118u
#define LASERAX_REG_COMP_SYNC_WIDTH 1
#define LASERAX_REG_COMP_SYNC_WORDS 1
#define LASERAX_REG_COMP_SYNC_SIGNED 0
#define LASERAX_REG_COMP_SYNC_RESET 0LL
/* comp_commit: with comp_sync = 1: loads ratio and comp_offset into the multiplier in this clock (both together). Bad value: a commit between the words of a wide register loads a half-written value (host side: words first, then commit) */
#define LASERAX_REG_COMP_COMMIT_OFFSET 0x120u
#define LASERAX_REG_COMP_COMMIT_WIDTH 1
#define LASERAX_REG_COMP_COMMIT_WORDS 1
#define LASERAX_REG_COMP_COMMIT_SIGNED 0
#define LASERAX_REG_COMP_COMMIT_RESET 0LL
/* pin_cfg: digital output pins (DESIGN 4.7, docs/CONTROLLER.md): bit 0 qz_window (0: qz is the index, one quadrature state at the home point Z; 1: qz is the reference window B..C, as ref_mark); bits 2:1 ab_rot (qa/qb encode out_pos + ab_rot: the A/B levels of the index state are those of (P/8 + ab_rot) mod 4, (0,0) at 0 and (1,1) at 2 for P a multiple of 32); bit 3 hiz_alarm (1: q_oe, the A/B/Z driver enable, is low while alarm is set). Reset 8: index at Z, no rotation, drivers off on alarm. Bad value: none (every value legal); a wrong ab_rot moves the A/B state of the index, so a gated counter misses it (its rising edge ungated still homes at Z) */
#define LASERAX_REG_PIN_CFG_OFFSET 0x128u
#define LASERAX_REG_PIN_CFG_WIDTH 4
#define LASERAX_REG_PIN_CFG_WORDS 1
#define LASERAX_REG_PIN_CFG_SIGNED 0
#define LASERAX_REG_PIN_CFG_RESET 8LL

/* X-macro over every register: X(NAME, OFFSET, WIDTH, SIGNED, RESET) */
#define LASERAX_REGS(X) \
    X(PERIOD, 0x10u, 13, 0, 256LL) \
    X(TBL_PERIOD, 0x18u, 13, 0, 256LL) \
    X(RATIO, 0x20u, 37, 0, 34789620252LL) \
    X(COMP_OFFSET, 0x30u, 64, 1, 0LL) \
    X(GLITCH_N, 0x40u, 8, 0, 2LL) \
    X(SW_DEBOUNCE, 0x48u, 16, 0, 16LL) \
    X(MIN_SPACING, 0x50u, 16, 0, 8LL) \
    X(PACE_M, 0x58u, 16, 0, 61LL) \
    X(BACKLOG_THR, 0x60u, 32, 0, 4096LL) \
    X(MARK_LEN, 0x68u, 13, 0, 64LL) \
    X(DAC_WIDTH, 0x70u, 5, 0, 16LL) \
    X(AMPLITUDE, 0x78u, 18, 0, 32767LL) \
    X(REHOME, 0x80u, 1, 0, 0LL) \
    X(CLEAR, 0x88u, 1, 0, 0LL) \
    X(TBL_WE, 0x90u, 1, 0, 0LL) \
    X(TBL_ADDR, 0x98u, 10, 0, 0LL) \
    X(TBL_DATA, 0xA0u, 17, 0, 0LL) \
    X(MAP_EN, 0xA8u, 1, 0, 0LL) \
    X(BANK_SEL, 0xB0u, 1, 0, 0LL) \
    X(MAP_ORIGIN0, 0xC0u, 38, 1, 0LL) \
    X(MAP_K0, 0xD0u, 5, 0, 10LL) \
    X(MAP_N0, 0xD8u, 11, 0, 1024LL) \
    X(MAP_ORIGIN1, 0xE0u, 38, 1, 0LL) \
    X(MAP_K1, 0xF0u, 5, 0, 10LL) \
    X(MAP_N1, 0xF8u, 11, 0, 1024LL) \
    X(MAP_WE, 0x100u, 1, 0, 0LL) \
    X(MAP_ADDR, 0x108u, 10, 0, 0LL) \
    X(MAP_DATA, 0x110u, 24, 1, 0LL) \
    X(COMP_SYNC, 0x118u, 1, 0, 0LL) \
    X(COMP_COMMIT, 0x120u, 1, 0, 0LL) \
    X(PIN_CFG, 0x128u, 4, 0, 8LL)

#endif /* LASERAX_REGS_C_H */
