// tb_generated_files — generated files are reproducible, and constants are what their formulas say.
//
// * hls/dds_table_default.h and rtl_ref/laserax_widths.vh are regenerated with the command recorded
//   in their own header (run with the lutgen / rtl_widths built next to this test) and must be
//   byte-identical.
// * The reset ratio of the HLS register block equals round(632.991 / 1.000271 / 78.125 * 2^32).
// * The table words in the default header equal the table routine for P = 256, amp = 32767.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "hls/laserax_top.h"
#include "tb/tb_util.h"
#include "host/dds_table.h"
#include "sysmodel/sim.h"
#include "tools/laserax/vectors.h"

namespace {

// Regenerates `target` with the command recorded in its header ("Command: PROGRAM ... TARGET ..."),
// PROGRAM run from the build directory and writing to a temporary file, and compares byte for byte.
void regenerate(tbu::result& res, const std::string& build, const std::string& target, const std::string& program) {
    std::string text, err;
    if (!res.check(lxt::read_file(target, text, &err), err)) return;
    const std::string key = "Command: ";
    const size_t k = text.find(key);
    if (!res.check(k != std::string::npos, "no command in the header of " + target)) return;
    const std::string cmd = text.substr(k + key.size(), text.find('\n', k) - k - key.size());
    const std::string tmp = "/tmp/laserax_tb_generated_" + std::to_string(::getpid()) + "_" + program;
    const size_t t = cmd.find(target);
    res.check(cmd.rfind(program + " ", 0) == 0 && t != std::string::npos, "unexpected command: " + cmd);
    if (t == std::string::npos) return;
    std::string run = build + "/" + cmd;
    run.replace(run.find(target), target.size(), tmp);
    res.check(std::system(run.c_str()) == 0, program + " failed: " + run);
    std::string regen;
    res.check(lxt::read_file(tmp, regen, &err), err);
    // the header records the command with the committed path; compare with it substituted back
    const size_t p = regen.find(tmp);
    if (p != std::string::npos) regen.replace(p, tmp.size(), target);
    res.check(regen == text, target + " differs from a fresh `" + cmd + "`");
    std::remove(tmp.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    tbu::result res("tb_generated_files", tbu::seed_from(argc, argv, 0));
    const char* bd = std::getenv("LASERAX_BUILD_DIR");
    const std::string build = bd ? bd : "build";
    regenerate(res, build, "hls/dds_table_default.h", "lutgen");
    // the reference RTL's widths, from the configuration structs of hls/ (tools/rtl_widths.cpp)
    regenerate(res, build, "rtl_ref/laserax_widths.vh", "rtl_widths");
    res.check(lx::laserax_top_cfg::RATIO_DEFAULT == lxt::ratio_for(632.991, 1.000271, 78.125),
              "RATIO_DEFAULT != round(632.991/1.000271/78.125*2^32) = " +
                  std::to_string(lxt::ratio_for(632.991, 1.000271, 78.125)));
    const std::vector<uint32_t> t = lxt::dds_table(LASERAX_DDS_TABLE_DEFAULT_PERIOD, LASERAX_DDS_TABLE_DEFAULT_AMPLITUDE);
    const uint32_t words[] = {LASERAX_DDS_TABLE_DEFAULT};
    res.check(t.size() == sizeof(words) / sizeof(words[0]), "default table size");
    for (size_t i = 0; i < t.size() && i < sizeof(words) / sizeof(words[0]); ++i)
        res.check(t[i] == words[i], "default table word " + std::to_string(i));
    return res.finish();
}
