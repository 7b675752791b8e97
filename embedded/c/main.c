/*
 * gdsmc from C on a microcontroller: the no_std build of libgdsmc (caller memory only, no
 * allocator in gdsmc, status codes, panic = abort), GRW Example 3 with 512 particles, seed 1,
 * stream 0, in a static buffer sized by gdsmc_sim_footprint. Prints T, T_bulk and a2 at
 * t = 0..8 with 17 significant digits over semihosting; embedded/run.sh compares them with the
 * same program built for the host against the std libgdsmc. Also checks that a bad value is
 * refused with the core's message. Returns 0 when every call succeeded.
 */
#include <stdio.h>
#include <string.h>
#include "gdsmc.h"

#define N 512
/* Room for the handle's header (3.5 KiB: the largest engine of the host's full build, a rough
 * mixture's time-stepped scheme in a host medium under the impact-speed law, with the header,
 * 3104 bytes since the handle holds the weighted scheme's room) and N particles of 32 bytes
 * (checked against the footprint). */
static _Alignas(32) unsigned char memory[3584 + N * 32];

static int check(gdsmc_status s, const char *what) {
    if (s != GDSMC_OK) {
        char msg[256];
        gdsmc_last_error(msg, sizeof msg);
        printf("error: %s failed (status %d): %s\n", what, (int)s, msg);
        return 1;
    }
    return 0;
}

int main(void) {
    gdsmc_config cfg;
    if (check(gdsmc_config_default(&cfg), "gdsmc_config_default")) return 1;
    cfg.n = N;
    size_t bytes = 0, align = 0;
    if (check(gdsmc_sim_footprint(cfg.n, &bytes, &align), "gdsmc_sim_footprint")) return 1;
    if (bytes > sizeof memory || align > 32) {
        printf("error: footprint %zu bytes, alignment %zu\n", bytes, align);
        return 1;
    }
    /* A bad value gets the core's words. */
    gdsmc_config bad = cfg;
    gdsmc_sim *sim = NULL;
    bad.restitution = 1.5;
    if (gdsmc_sim_init_in(memory, sizeof memory, &bad, &sim) != GDSMC_INVALID_ARGUMENT) return 1;
    char msg[256];
    gdsmc_last_error(msg, sizeof msg);
    printf("refused: %s\n", msg);
    if (strcmp(msg, "config.restitution must lie in (0, 1], got 1.5") != 0) return 1;

    if (check(gdsmc_sim_init_in(memory, sizeof memory, &cfg, &sim), "gdsmc_sim_init_in")) return 1;
    for (int i = 0; i <= 8; i++) {
        gdsmc_observables o;
        gdsmc_status s = i == 0 ? gdsmc_sim_observables(sim, &o)
                                : gdsmc_sim_advance(sim, (double)i, &o);
        if (check(s, "gdsmc_sim_advance")) return 1;
        printf("t=%d T=%.17g T_bulk=%.17g a2=%.17g collisions=%llu\n", i, o.temperature,
               o.temperature_bulk, o.a2, (unsigned long long)o.collisions);
    }
    if (check(gdsmc_sim_destroy(&sim), "gdsmc_sim_destroy")) return 1;
    printf("ok\n");
    return 0;
}
