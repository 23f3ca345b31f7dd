// tb_dds_quality — the hls DDS against analytic limits, for every period preset and the corner
// periods 8 and 4096: one period of codes is analysed by the golden analysis (Eigen DFT, long
// double reference) and must show
//   * rounding error <= 0.5 LSB everywhere (round-half-away of the exact value),
//   * SNR within 1.5 dB of the uniform-rounding limit 10 log10(6 amp^2) (98.1 dB at 16 bits; a
//     table with only P/8 independent rounding errors scatters by ~0.7 dB about it, while truncation
//     instead of rounding would lose 6 dB),
//   * SFDR >= 90 dBc at amplitude 32767 (the table rounding is the only error source).
// The figures are printed for the issue note.
#include <vector>

#include "golden/dds_analysis.h"
#include "hls/dds_sincos.h"
#include "tb/tb_util.h"
#include "host/dds_table.h"

int main(int argc, char** argv) {
    tbu::result res("tb_dds_quality", tbu::seed_from(argc, argv, 0));
    const int periods[] = {8, 256, 320, 512, 640, 1280, 4096};
    const int amps[] = {32767, 131071, 2047};
    std::printf("  %6s %7s %10s %10s %10s %10s %10s\n", "P", "amp", "max_err", "rms_err", "SNR_dB", "ideal_dB", "SFDR_dBc");
    for (int amp : amps) {
        for (int P : periods) {
            lx::dds_sincos d;
            const std::vector<uint32_t> t = lxt::dds_table(P, amp);
            for (size_t k = 0; k < t.size(); ++k) d.load(static_cast<unsigned>(k), t[k]);
            std::vector<int64_t> s, c;
            // the codes of call k belong to phase k - 1 (two stages, DESIGN 4.6): the first call
            // shows the reset codes and is dropped, calls 1..P give phases 0..P-1
            for (int k = 0; k <= P; ++k) {
                const lx::dds_sincos::out_t o = d.step(1, P, amp);
                if (k == 0) continue;
                s.push_back(o.sin.to_int64());
                c.push_back(o.cos.to_int64());
            }
            const golden::dds_quality q = golden::analyse_dds(s, c, amp);
            std::printf("  %6d %7d %10.4f %10.4f %10.2f %10.2f %10.2f\n", P, amp, q.max_err_lsb, q.rms_err_lsb, q.snr_db,
                        q.ideal_snr_db, q.sfdr_dbc);
            const std::string tag = "P=" + std::to_string(P) + " amp=" + std::to_string(amp);
            res.check(q.max_err_lsb <= 0.5 + 1e-9, tag + ": rounding error above 0.5 LSB");
            if (P >= 64) res.check(q.snr_db >= q.ideal_snr_db - 1.5, tag + ": SNR below the rounding limit");
            if (amp == 32767 && P >= 64) res.check(q.sfdr_dbc >= 90.0, tag + ": SFDR below 90 dBc");
        }
    }
    return res.finish();
}
