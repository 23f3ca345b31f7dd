// trace.h — writers for out/trace.csv (a row whenever a column other than true_nm changes, or
// every clock) and out/trace.vcd (GTKWave-readable, one timestep per clock of 10 ns).
#ifndef LASERAX_TOOLS_TRACE_H
#define LASERAX_TOOLS_TRACE_H

#include <cstdio>
#include <string>

#include "sysmodel/homing.h"

namespace lxt {

class trace_writer {
public:
    // Opens both files; returns false with a message in err on failure.
    bool open(const std::string& dir, bool every_clock, int period, const std::string& command, std::string* err);
    void add(const trace_row& r);
    void close();
    ~trace_writer() { close(); }
    long long csv_rows() const { return rows_; }

private:
    FILE* csv_ = nullptr;
    FILE* vcd_ = nullptr;
    bool every_ = false;
    int period_ = 256;
    bool have_prev_ = false;
    long long rows_ = 0;
    long long vals_[16] = {};
};

}  // namespace lxt

#endif
