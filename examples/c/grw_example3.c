/*
 * GRW Example 3 from C: the heated Maxwell gas (alpha = 1/2, beta = 1, gamma = 4,
 * C0 = 1/(4 pi)) relaxing from T = 1 to T_inf = 8/3. Runs M independent ensembles (streams
 * 0..M-1 of one seed, as `gdsmc run` does) and prints the mean temperature with its 99.9%
 * confidence half-width (gdsmc_mean_interval: Student's t for M - 1 degrees of freedom at the
 * level of 3.2 normal sigma, as `gdsmc run` computes it) beside the exact mean at this n,
 * GRW (13)-(14) at finite n (gdsmc_reference_find: the column `T_mean_n` that `gdsmc run`
 * writes, to the bit) and the Boltzmann limit GRW (13), T(t) = 8/3 + (1 - 8/3) exp(-3t/4).
 * The program exits with 1 when a point misses its interval of the exact mean (nine points
 * at 99.9% each: a correct engine fails about one seed in 80).
 *
 * Build (from the repository root, after `cargo build --release -p gdsmc-ffi`):
 *   cc -std=c11 examples/c/grw_example3.c -Iinclude target/release/libgdsmc.a -lm -lpthread -ldl \
 *      -o target/grw_example3
 * or, after `bash ffi/install.sh PREFIX`, with pkg-config or CMake's find_package(gdsmc).
 */
#include <math.h>
#include <stdio.h>
#include "gdsmc.h"

#define M 40
#define STEPS 8

static int check(gdsmc_status s, const char *what) {
    if (s != GDSMC_OK) {
        char msg[512];
        gdsmc_last_error(msg, sizeof msg);
        fprintf(stderr, "%s failed (status %d): %s\n", what, (int)s, msg);
        return 1;
    }
    return 0;
}

int main(void) {
    gdsmc_mean temperature[STEPS + 1] = {{0}};
    double times[STEPS + 1], mean_at_n[STEPS + 1], limit[STEPS + 1];
    for (int i = 0; i <= STEPS; i++) times[i] = (double)i;
    gdsmc_config cfg;
    if (check(gdsmc_config_default(&cfg), "gdsmc_config_default")) return 1;
    cfg.n = 4096; /* the defaults are GRW Example 3 */
    printf("gdsmc %s: GRW Example 3, n = %llu, %d ensembles\n", gdsmc_version(),
           (unsigned long long)cfg.n, M);
    for (int k = 0; k < M; k++) {
        gdsmc_sim *sim = NULL;
        cfg.stream = (uint64_t)k;
        if (check(gdsmc_sim_create(&cfg, &sim), "gdsmc_sim_create")) return 1;
        for (int i = 0; i <= STEPS; i++) {
            gdsmc_observables o;
            if (check(gdsmc_sim_advance(sim, times[i], &o), "gdsmc_sim_advance")) return 1;
            if (check(gdsmc_mean_add(&temperature[i], o.temperature), "gdsmc_mean_add")) return 1;
        }
        if (check(gdsmc_sim_destroy(&sim), "gdsmc_sim_destroy")) return 1;
    }
    /* The references gdsmc run writes beside its means, computed by the same code. */
    gdsmc_reference at_n, boltzmann;
    if (check(gdsmc_reference_find(&cfg, times, STEPS + 1, "T_mean_n", &at_n, mean_at_n),
              "gdsmc_reference_find T_mean_n") ||
        check(gdsmc_reference_find(&cfg, times, STEPS + 1, "T_exact", &boltzmann, limit),
              "gdsmc_reference_find T_exact"))
        return 1;
    printf("%s, %s (%s)\n", at_n.name, boltzmann.name, at_n.source);
    printf("%6s %12s %12s %12s %12s\n", "t", "T", "99.9% CI", at_n.name, boltzmann.name);
    int outside = 0;
    for (int i = 0; i <= STEPS; i++) {
        double mean, ci;
        if (check(gdsmc_mean_interval(&temperature[i], &mean, &ci), "gdsmc_mean_interval"))
            return 1;
        printf("%6.2f %12.6f %12.6f %12.6f %12.6f\n", times[i], mean, ci, mean_at_n[i], limit[i]);
        outside += fabs(mean - mean_at_n[i]) > ci;
    }
    printf("%d of %d points outside the 99.9%% confidence interval\n", outside, STEPS + 1);
    return outside > 0;
}
