// One core's memory bandwidth for the working sets of bench/lammps_pair_cost.py (docs/dem.md, "Is the step
// memory-bound?"): a read pass (a sum) and a read-modify-write pass (x <- a x + b, in place, as a contact law steps
// its state) over arrays of 0.5 MB (a core's L2 holds it), 33 MB (the 20^3 lattice's mdr/visco histories) and
// 512 MB (beyond the L3), each the best of several repetitions (the host is shared), in GB/s of bytes read plus
// bytes written.
//
//     g++ -O3 -march=native -std=c++20 bench/stream_bandwidth.cpp -o /tmp/stream_bandwidth && /tmp/stream_bandwidth

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main() {
    for (const double megabytes : {0.5, 33.0, 512.0}) {
        const auto count = static_cast<std::size_t>(megabytes * 1e6 / sizeof(double));
        std::vector<double> data(count, 1.0);
        // Enough passes for about 4 GB of traffic per repetition.
        const int passes = std::max(1, static_cast<int>(4e3 / megabytes));
        double best_read = 0.0, best_update = 0.0, sink = 0.0;
        for (int repetition = 0; repetition < 5; ++repetition) {
            auto start = std::chrono::steady_clock::now();
            for (int pass = 0; pass < passes; ++pass) {
                double sums[8] = {};  // eight chains, so that the adds' latency does not bound the pass
                for (std::size_t i = 0; i + 8 <= count; i += 8) {
                    for (std::size_t lane = 0; lane < 8; ++lane) sums[lane] += data[i + lane];
                }
                for (const double sum : sums) sink += sum;
            }
            best_read = std::max(best_read, passes * megabytes * 1e6 / seconds_since(start) / 1e9);
            start = std::chrono::steady_clock::now();
            for (int pass = 0; pass < passes; ++pass) {
                for (double& value : data) value = 0.999 * value + 0.001;
            }
            best_update = std::max(best_update, 2.0 * passes * megabytes * 1e6 / seconds_since(start) / 1e9);
            sink += data[count / 2];
        }
        std::printf("%8.1f MB: read %6.1f GB/s, read-modify-write %6.1f GB/s (read + written)%s\n", megabytes,
                    best_read, best_update, sink == 0.0 ? " " : "");
    }
}
