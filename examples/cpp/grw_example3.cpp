// GRW Example 3 from C++ through the RAII wrapper include/gdsmc.hpp: mean temperature of
// M ensembles (streams 0..M-1) with its 99.9% confidence half-width (gdsmc::Mean: Student's t,
// 39 degrees of freedom, at the level of 3.2 normal sigma, as `gdsmc run` computes it) beside
// the exact mean at this n (gdsmc::reference "T_mean_n", GRW (13)-(14), the command's column);
// exits with 1 when a point misses its interval (as examples/c/grw_example3.c).
//
// Build (one line): c++ -std=c++17 examples/cpp/grw_example3.cpp -Iinclude
//   target/release/libgdsmc.a -lm -lpthread -ldl -o target/grw_example3_cpp
#include <cmath>
#include <cstdio>
#include <vector>

#include "gdsmc.hpp"

int main() {
    const int M = 40, STEPS = 8;
    std::vector<gdsmc::Mean> temperature(STEPS + 1);
    std::vector<double> times;
    for (int i = 0; i <= STEPS; ++i) times.push_back(i);
    gdsmc::Reference exact;
    try {
        gdsmc_config cfg = gdsmc::default_config();  // GRW Example 3
        cfg.n = 4096;
        for (int k = 0; k < M; ++k) {
            cfg.stream = static_cast<uint64_t>(k);
            gdsmc::Simulation sim(cfg);
            for (int i = 0; i <= STEPS; ++i) temperature[i].add(sim.advance(times[i]).temperature);
        }
        exact = gdsmc::reference(cfg, times, "T_mean_n");
        // Errors are exceptions: a restitution outside (0, 1] is refused with its message.
        try {
            gdsmc_config bad = cfg;
            bad.restitution = 1.5;
            gdsmc::Simulation s(bad);
            std::printf("bad configuration accepted\n");
            return 1;
        } catch (const gdsmc::Error &e) {
            std::printf("refused as expected (status %d): %s\n", static_cast<int>(e.status()), e.what());
        }
        // So is an advance above the simulation's work limit (about 8190 candidates per unit
        // time here), before it runs anything.
        try {
            gdsmc::Simulation s(cfg);
            s.set_work_limit(1e3);
            s.advance(1.0);
            std::printf("advance above the work limit accepted\n");
            return 1;
        } catch (const gdsmc::Error &e) {
            if (e.status() != GDSMC_TOO_MUCH_WORK) {
                std::fprintf(stderr, "work limit: %s\n", e.what());
                return 1;
            }
            std::printf("refused as expected (status %d): %s\n", static_cast<int>(e.status()), e.what());
        }
    } catch (const gdsmc::Error &e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    std::printf("%6s %12s %12s %12s (%s)\n", "t", "T", "99.9% CI", exact.name.c_str(),
                exact.source.c_str());
    int outside = 0;
    for (int i = 0; i <= STEPS; ++i) {
        auto [mean, ci] = temperature[i].interval();
        std::printf("%6.2f %12.6f %12.6f %12.6f\n", times[i], mean, ci, exact.values[i]);
        outside += std::fabs(mean - exact.values[i]) > ci;
    }
    std::printf("%d of %d points outside the 99.9%% confidence interval\n", outside, STEPS + 1);
    return outside > 0;
}
