# run_hls.tcl — Vitis HLS flow for the laserax core (top: laserax_top in hls/laserax_top.cpp).
#
#   vitis_hls -f scripts/run_hls.tcl -tclargs csim=1 csynth=1 cosim=0
#   CSYNTH=1 COSIM=1 LASERAX_PART=xcku5p-ffvb676-2-e vitis_hls -f scripts/run_hls.tcl
#
# Settings, in increasing priority: defaults below, environment variables, key=value arguments.
#   part      LASERAX_PART      default xczu3eg-sbva484-1-e
#   clock_ns  LASERAX_CLOCK_NS  default 10 (100 MHz)
#   csim      CSIM              default 1   C simulation of tb/tb_hls_csim.cpp
#   csynth    CSYNTH            default 1   C synthesis
#   cosim     COSIM             default 0   C/RTL co-simulation (needs csynth results)
#   export    EXPORT            default 0   export_design -format ip_catalog
#   reset     RESET             default 0   open the project with -reset (drops earlier results)
# The project folder laserax_hls/ is created in the repository root (ignored by git).

set part     xczu3eg-sbva484-1-e
set clock_ns 10
set csim     1
set csynth   1
set cosim    0
set export   0
set reset    0

set envmap {part LASERAX_PART clock_ns LASERAX_CLOCK_NS csim CSIM csynth CSYNTH cosim COSIM export EXPORT reset RESET}
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
            if {[lsearch -exact {part clock_ns csim csynth cosim export reset} $key] < 0} {
                puts "run_hls.tcl: unknown setting '$key' (known: part clock_ns csim csynth cosim export reset)"
                exit 2
            }
            set $key $value
        }
    }
}

# Work from the repository root (the folder above this script), so paths are stable.
set root [file normalize [file join [file dirname [info script]] ..]]
cd $root
# Absolute -I: csim compiles inside the solution folder, where a relative -I. would not resolve.
set cflags "-std=c++14 -DLASERAX_USE_AP_TYPES -I$root"

puts "run_hls.tcl: part=$part clock=${clock_ns}ns csim=$csim csynth=$csynth cosim=$cosim export=$export"

if {$reset} {
    open_project -reset laserax_hls
} else {
    open_project laserax_hls
}
set_top laserax_top
add_files hls/laserax_top.cpp -cflags $cflags
add_files -tb tb/tb_hls_csim.cpp -cflags $cflags
# the C-simulation testbench compares the top with the golden chain
foreach f [glob -nocomplain golden/*.cpp] { add_files -tb $f -cflags $cflags }

open_solution solution1 -flow_target vivado
set_part $part
create_clock -period $clock_ns -name default

if {$csim}   { csim_design }
if {$csynth} { csynth_design }
if {$cosim}  { cosim_design -rtl verilog }
if {$export} { export_design -format ip_catalog }
exit
