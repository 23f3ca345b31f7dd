# run_hls.tcl — Vitis HLS flow for the laserax core (top: laserax_axil in hls/laserax_axil.cpp).
#
#   vitis_hls -f scripts/run_hls.tcl -tclargs csim=1 csynth=1 cosim=0
#   CSYNTH=1 COSIM=1 LASERAX_PART=xcku5p-ffvb676-2-e vitis_hls -f scripts/run_hls.tcl
#
# Settings, in increasing priority: defaults below, environment variables, key=value arguments.
#   part      LASERAX_PART      default xczu3eg-sbva484-1-e
#   clock_ns  LASERAX_CLOCK_NS  default 10 (100 MHz)
#   csim      CSIM              default 1   C simulation of tb/tb_hls_csim.cpp
#   csynth    CSYNTH            default 1   C synthesis
#   cosim     COSIM             default 0   C/RTL co-simulation (needs csynth results): the same
#                                           testbench; possible because the top's return is on
#                                           the s_axilite slave with its arguments (ap_ctrl_hs
#                                           through AXI4-Lite; the II = 1 pipeline free-runs once
#                                           started with auto_restart, see hls/laserax_axil.cpp)
#   export    EXPORT            default 0   export_design -format ip_catalog
#   debug_taps LASERAX_DEBUG_TAPS default 0  -DLASERAX_HLS_DEBUG_TAPS=<0|1> for design and
#                                           testbench: 0 drops the debug taps of the top's
#                                           outputs (the deployed core, as DEBUG_TAPS = 0 in
#                                           rtl_ref), 1 drives them (hls/laserax_axil.h)
#   reset     RESET             default 0   open the project with -reset (drops earlier results)
# The project folder laserax_hls/ is created in the repository root (ignored by git).

set part     xczu3eg-sbva484-1-e
set clock_ns 10
set csim     1
set csynth   1
set cosim    0
set export   0
set reset    0
set debug_taps 0

set envmap {part LASERAX_PART clock_ns LASERAX_CLOCK_NS csim CSIM csynth CSYNTH cosim COSIM export EXPORT reset RESET
            debug_taps LASERAX_DEBUG_TAPS}
foreach {var envname} $envmap {
    if {[info exists ::env($envname)] && $::env($envname) ne ""} {
        set $var $::env($envname)
    }
}
if {[info exists argv]} {
    foreach arg $argv {
        if {[regexp {^-*([A-Za-z_]+)=(.*)$} $arg -> key value]} {
            set key [string tolower $key]
            if {$key eq "clock"} { set key clock_ns }
            if {[lsearch -exact {part clock_ns csim csynth cosim export reset debug_taps} $key] < 0} {
                puts "run_hls.tcl: unknown setting '$key' (known: part clock_ns csim csynth cosim export reset debug_taps)"
                exit 2
            }
            set $key $value
        }
    }
}

# Work from the repository root (the folder above this script), so paths are stable.
set root [file normalize [file join [file dirname [info script]] ..]]
cd $root

# The files of the C simulation: the design, and the testbench with the golden chain it compares
# against and the host's initialisation call it writes the registers with (host/ip_init.cpp and
# the register table it reads): exactly the sources CMake compiles for tb_hls_csim (the .cpp files
# tb/tb_hls_csim.cpp reaches through its #includes; no Eigen). CTest hls_tcl_files compares these two lists with
# <build>/hls_csim_sources.txt, so they cannot drift (scripts/check_hls_tcl.py).
set design_files {
    hls/laserax_axil.cpp
}
set tb_files {
    tb/tb_hls_csim.cpp
    golden/laserax_top.cpp
    golden/dds_sincos.cpp
    golden/error_map.cpp
    golden/input_filter.cpp
    golden/output_pacer.cpp
    golden/pulse_multiplier.cpp
    golden/quad_decoder.cpp
    golden/rephase.cpp
    host/ip_init.cpp
    host/regmap_table.cpp
}

# Compile flags, the same for design and testbench: C++14 (the Vitis front end), the ap_int back
# end of hls/lx_types.h (Vitis supplies ap_int.h itself), the debug-taps switch of the top,
# includes from the repository root.
# Absolute -I: csim compiles inside the solution folder, where a relative -I. would not resolve.
# csim_design compiles without optimisation (its default, no -O); `make test` runs the same
# testbench built with the vendor ap_int.h at -O0 and -O2 (CTest tb_hls_csim.ap_O0 / .ap_O2).
if {$debug_taps ne "0" && $debug_taps ne "1"} {
    puts "run_hls.tcl: debug_taps must be 0 or 1, not '$debug_taps'"
    exit 2
}
set cflags "-std=c++14 -DLASERAX_USE_AP_TYPES -DLASERAX_HLS_DEBUG_TAPS=$debug_taps -I$root"

puts "run_hls.tcl: part=$part clock=${clock_ns}ns csim=$csim csynth=$csynth cosim=$cosim export=$export debug_taps=$debug_taps"

if {$reset} {
    open_project -reset laserax_hls
} else {
    open_project laserax_hls
}
set_top laserax_axil
foreach f $design_files { add_files $f -cflags $cflags }
foreach f $tb_files { add_files -tb $f -cflags $cflags }

open_solution solution1 -flow_target vivado
set_part $part
create_clock -period $clock_ns -name default

if {$csim}   { csim_design }
if {$csynth} { csynth_design }
# co-simulation drives every call through the AXI4-Lite adapter: the testbench's default of
# 400000 calls would be 400000 bus transactions, so cosim runs it with 20000 calls after the
# initialisation (homing and Z need at least 10000; tb_hls_csim refuses fewer), plus the 3000
# calls before it in which the core must hold cfg_err on its zero registers
if {$cosim}  { cosim_design -rtl verilog -argv {--calls 20000} }
if {$export} { export_design -format ip_catalog }
exit
