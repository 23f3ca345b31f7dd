// laserax_widths.vh — widths of the rtl_ref/ ports and datapaths, from the configuration
// structs of hls/ (DESIGN.md §3; each macro names its source).
// GENERATED FILE, do not edit. Command: rtl_widths --out rtl_ref/laserax_widths.vh
// Every rtl_ref/ block includes it (`include "laserax_widths.vh", found next to the
// including file: Yosys by default, Icarus with -grelative-include).
`ifndef LASERAX_WIDTHS_VH
`define LASERAX_WIDTHS_VH

// chain (lx::axis_widths)
`define LX_W_STEP 2                      // lx::step_t: -1, 0, +1
`define LX_W_RAW 32                      // axis_widths::W_RAW: raw laser count
`define LX_R_FRAC 32                     // axis_widths::R_FRAC: ratio fraction bits
`define LX_W_RATIO 37                    // axis_widths::W_RATIO: ratio Q5.32
`define LX_W_ACC 70                      // axis_widths::W_ACC: exact N*R + OFF
`define LX_W_OFFSET 64                   // axis_widths::W_OFFSET: comp offset Q32.32
`define LX_W_POS 38                      // axis_widths::W_POS: positions, output counts
`define LX_W_DELTA 39                    // axis_widths::W_DELTA: comp(t) - comp(t-1)
`define LX_W_BACKLOG 40                  // axis_widths::W_BACKLOG: pacer backlog
`define LX_W_P 13                        // axis_widths::W_P: period register
`define LX_W_PH 12                       // axis_widths::W_PH: phase 0..P-1
`define LX_W_TBL 17                      // axis_widths::W_TBL: DDS table word
`define LX_W_TBL_ADDR 10                 // axis_widths::W_TBL_ADDR: DDS table address
`define LX_W_DAC 18                      // axis_widths::W_DAC_MAX: sin/cos codes
`define LX_W_DACW 5                      // axis_widths::W_DACW: dac_width register

// quad_decoder (lx::quad_decoder_cfg)
`define LX_QD_W_GLITCH 8                 // quad_decoder_cfg::W_GLITCH
`define LX_QD_W_SPACING 16               // quad_decoder_cfg::W_SPACING
`define LX_QD_W_ERRCNT 8                 // quad_decoder_cfg::W_ERRCNT

// output_pacer (lx::output_pacer_cfg)
`define LX_OP_W_PACE 16                  // output_pacer_cfg::W_PACE
`define LX_OP_W_THR 32                   // output_pacer_cfg::W_THR
`define LX_OP_W_ADD 18                   // output_pacer_cfg::W_ADD: error-map delta

// error_map (lx::error_map_cfg)
`define LX_EM_W_K 5                      // error_map_cfg::W_K: spacing_log2 register
`define LX_EM_W_N 11                     // error_map_cfg::W_N: n_points register
`define LX_EM_W_ADDR 10                  // error_map_cfg::W_ADDR: table address
`define LX_EM_W_CORR 24                  // error_map_cfg::W_CORR: table word
`define LX_EM_W_C 17                     // error_map_cfg::W_C: correction
`define LX_EM_W_CDELTA 18                // error_map_cfg::W_CDELTA: corr' - corr

// rephase (lx::rephase_cfg)
`define LX_W_STAGE 2                     // rephase_cfg::W_STAGE: stage output

// dds_sincos (lx::dds_sincos_cfg)
`define LX_DDS_W_AMP 18                  // dds_sincos_cfg::W_AMP: amplitude register
`define LX_DDS_W_R 11                    // dds_sincos_cfg::W_R: r and P/4 - r

// laserax_top (lx::laserax_top_cfg)
`define LX_TOP_W_DEBOUNCE 16             // laserax_top_cfg::W_DEBOUNCE
`define LX_TOP_W_PIN_CFG 4               // laserax_top_cfg::W_PIN_CFG: pin_cfg register

// encoder_counter (lx::encoder_counter_cfg)
`define LX_EC_W_CNT 32                   // encoder_counter_cfg::W_CNT: counters
`define LX_EC_W_SRC 2                    // encoder_counter_cfg::W_SRC: source register
`define LX_EC_W_INC 32                   // encoder_counter_cfg::W_INC: simulation rate
`define LX_EC_W_SCALE 32                 // encoder_counter_cfg::W_SCALE: Q8.24
`define LX_EC_W_PER 16                   // encoder_counter_cfg::W_PER: correction period
`define LX_EC_W_POSIN 32                 // encoder_counter_cfg::W_POSIN
`define LX_EC_W_CORR 40                  // encoder_counter_cfg::W_CORR

// pso (lx::pso_cfg)
`define LX_PSO_N_AXES 3                  // pso_cfg::N_AXES: axes, axis_mask register
`define LX_PSO_D_FRAC 32                 // pso_cfg::D_FRAC: distance fraction bits
`define LX_PSO_W_DIST 56                 // pso_cfg::W_DIST: fire_dist, array entries
`define LX_PSO_W_REM 58                  // pso_cfg::W_REM: dist, signed
`define LX_PSO_K_MAX 16                  // pso_cfg::K_MAX: longest tracking window
`define LX_PSO_W_K 5                     // pso_cfg::W_K: win_k register
`define LX_PSO_S_MAX 768                 // pso_cfg::S_MAX: chord ROM, last address
`define LX_PSO_W_S 10                    // pso_cfg::W_S: chord ROM address
`define LX_PSO_W_CHORD 37                // pso_cfg::W_CHORD: chord ROM word
`define LX_PSO_W_INCR 38                 // pso_cfg::W_INCR: estimate step
`define LX_PSO_W_INC 32                  // pso_cfg::W_INC: part-speed rate Q0.32
`define LX_PSO_W_ADDR 6                  // pso_cfg::W_ADDR: array address
`define LX_PSO_W_LEN 7                   // pso_cfg::W_LEN: arr_len register, index
`define LX_PSO_W_PW 16                   // pso_cfg::W_PW: pulse width register
`define LX_PSO_W_GAP 16                  // pso_cfg::W_GAP: min_period register
`define LX_PSO_W_FCNT 32                 // pso_cfg::W_FCNT: emitted-pulse counter
`define LX_PSO_W_OVL 16                  // pso_cfg::W_OVL: overlap counter
`define LX_PSO_W_PROD 48                 // pso_cfg::W_PROD: inc * min_period
`define LX_PSO_W_SPHI 33                 // pso_cfg::W_SPHI: spacing shift-add upper part
`define LX_PSO_W_SRC 2                   // pso_cfg::W_SRC: win_src register

`endif
