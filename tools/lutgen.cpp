// lutgen — writes the dds_sincos table files.
//   lutgen --period P --amplitude A --header FILE   C header for hls/ (power-up RAM contents)
//   lutgen --period P --amplitude A --hex FILE      $readmemh file (1024 words) for rtl_ref/ and vectors
// The command line is recorded in the header of every file written.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

#include "host/dds_table.h"

int main(int argc, char** argv) {
    int period = 256, amplitude = 32767;
    std::string header, hex;
    std::string cmd = "lutgen";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto need = [&](const char* what) -> std::string {
            if (i + 1 >= argc) {
                std::cerr << "lutgen: " << a << " needs " << what << "\n";
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--period") period = std::atoi(need("a period").c_str());
        else if (a == "--amplitude") amplitude = std::atoi(need("an amplitude").c_str());
        else if (a == "--header") header = need("a file");
        else if (a == "--hex") hex = need("a file");
        else {
            std::cerr << "lutgen: unknown option " << a
                      << "\nusage: lutgen --period P --amplitude A [--header FILE] [--hex FILE]\n";
            return 2;
        }
    }
    for (int i = 1; i < argc; ++i) cmd += std::string(" ") + argv[i];
    std::string err;
    if (lxt::dds_table(period, amplitude, &err).empty()) {
        std::cerr << "lutgen: " << err << "\n";
        return 2;
    }
    const int depth = 1024;
    if (!header.empty()) {
        std::ofstream f(header);
        f << lxt::dds_table_header(period, amplitude, depth, cmd);
        if (!f) { std::cerr << "lutgen: cannot write " << header << "\n"; return 1; }
    }
    if (!hex.empty()) {
        std::ofstream f(hex);
        f << lxt::dds_table_hex(period, amplitude, depth, cmd);
        if (!f) { std::cerr << "lutgen: cannot write " << hex << "\n"; return 1; }
    }
    return 0;
}
