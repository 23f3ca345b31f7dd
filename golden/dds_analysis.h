// golden/dds_analysis.h — spectral and error analysis of one period of sin/cos DAC codes against
// the exact (long double) waveform, with Eigen. Used by tb_dds_quality to hold the DDS to its
// analytic limits (rounding error <= 0.5 LSB, quantisation SNR, spur-free dynamic range).
#pragma once
#include <cstdint>
#include <vector>

namespace golden {

struct dds_quality {
    double max_err_lsb = 0;   // max |code - amp*sin| over sin and cos
    double rms_err_lsb = 0;   // rms of the same
    double snr_db = 0;        // carrier power / error power
    double sfdr_dbc = 0;      // carrier bin / largest other bin of the DFT (sin + j cos)
    double ideal_snr_db = 0;  // 10 log10(6 amp^2): uniform rounding noise of 1/12 LSB^2
};

// sin_codes[k], cos_codes[k] for phase k = 0..P-1 of a period P, amplitude amp.
dds_quality analyse_dds(const std::vector<int64_t>& sin_codes, const std::vector<int64_t>& cos_codes, int64_t amp);

}  // namespace golden
