// ip_init.cpp — see ip_init.h.
#include "host/ip_init.h"

namespace lxt {

namespace {

namespace rm = regmap;

// a register the core acts on in every clock it is 1: the pulses and the table write enables
bool is_action(const rm::reg_info& r) {
    return r.acc == rm::access::pulse || (r.acc == rm::access::port && r.width == 1);
}

// the words of register r holding value v, low word first
void write_register(const rm::reg_info& r, int64_t v, const bus_write_fn& write) {
    const uint64_t bits = rm::to_bits(r, v);
    for (int w = 0; w < r.words(); ++w)
        write(r.offset + 4u * static_cast<uint32_t>(w), static_cast<uint32_t>(bits >> (32 * w)));
}

}  // namespace

bool init_registers(const axis_settings& image, const bus_write_fn& write, std::string* err) {
    for (int i = 0; i < rm::kNumRegs; ++i) {
        const rm::reg_info& r = rm::kRegs[i];
        const int64_t v = rm::get(image, i);
        std::string why;
        if (!rm::fits(r, v))
            why = "does not fit its width";
        else if (is_action(r) && v != 0)
            why = "is 1: the core acts on it in every clock it is 1 (an image holds 0 there)";
        if (!why.empty()) {
            if (err) *err = std::string("init_registers: ") + r.name + " = " + std::to_string(v) + " " + why;
            return false;
        }
    }
    const rm::reg_info& sync = rm::kRegs[rm::idx::comp_sync];
    const rm::reg_info& commit = rm::kRegs[rm::idx::comp_commit];
    write_register(sync, 1, write);  // 1.
    for (int i = 0; i < rm::kNumRegs; ++i)  // 2.
        if (i != rm::idx::comp_sync && i != rm::idx::comp_commit) write_register(rm::kRegs[i], rm::get(image, i), write);
    write_register(commit, 1, write);  // 3.
    write_register(commit, 0, write);
    write_register(sync, 0, write);  // 4.
    return true;
}

int init_register_writes() {
    int n = 4;  // comp_sync twice, comp_commit twice
    for (int i = 0; i < rm::kNumRegs; ++i)
        if (i != rm::idx::comp_sync && i != rm::idx::comp_commit) n += rm::kRegs[i].words();
    return n;
}

void start_core(const bus_write_fn& write) { write(kApCtrlOffset, kApStart | kApAutoRestart); }

}  // namespace lxt
