/*
 * The C ABI and the `gdsmc` command run the same engine: this program reads a scene file
 * (gdsmc_config_from_toml, the command's own scene reader), creates stream 0 of the scene's
 * seed, advances it to the observation times read from standard input (one per line, as
 * strtod reads the command's observables.csv), and prints, per time, the observables the
 * command writes for one ensemble with 17 significant digits:
 *   t,T,T_bulk,V_x,V_y,V_z,v4,v6,a2,a3
 * tests/c/same_as_command.sh compares them with `gdsmc run SCENE --ensembles 1` bit for bit.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include "gdsmc.h"
#include "scene_file.h"

int main(int argc, char **argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: %s SCENE.toml < times\n", argv[0]);
        return 2;
    }
    gdsmc_config cfg;
    int bad = config_of(argv[1], &cfg);
    if (bad) return bad;
    gdsmc_status s;
    gdsmc_sim *sim = NULL;
    if (check(gdsmc_sim_create(&cfg, &sim), "gdsmc_sim_create")) return 1;
    char line[128];
    printf("t,T,T_bulk,V_x,V_y,V_z,v4,v6,a2,a3");
    /* A mixture's species columns, named as in observables.csv. */
    if (cfg.species > 0) printf(",T_mix");
    for (uint32_t k = 0; k < cfg.species; k++) printf(",T_s%u,T_s%u_ratio,a2_s%u", k, k, k);
    /* A rough gas's rotation columns. */
    if (cfg.rough) printf(",T_rot,theta,a2_rot,cw2");
    printf("\n");
    while (fgets(line, sizeof line, stdin)) {
        double t = strtod(line, NULL);
        gdsmc_observables o;
        s = t == 0.0 ? gdsmc_sim_observables(sim, &o) : gdsmc_sim_advance(sim, t, &o);
        if (check(s, "gdsmc_sim_advance")) {
            gdsmc_sim_destroy(&sim);
            return 1;
        }
        printf("%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", t,
               o.temperature, o.temperature_bulk, o.bulk_velocity[0], o.bulk_velocity[1],
               o.bulk_velocity[2], o.v4, o.v6, o.a2, o.a3);
        for (uint32_t k = 0; k < cfg.species; k++) {
            gdsmc_species_observables so;
            if (check(gdsmc_sim_species(sim, k, &so), "gdsmc_sim_species")) {
                gdsmc_sim_destroy(&sim);
                return 1;
            }
            if (k == 0) printf(",%.17g", so.mixture_temperature);
            printf(",%.17g,%.17g,%.17g", so.temperature, so.temperature_ratio, so.a2);
        }
        if (cfg.rough) {
            gdsmc_rotation_observables r;
            if (check(gdsmc_sim_rotation(sim, &r), "gdsmc_sim_rotation")) {
                gdsmc_sim_destroy(&sim);
                return 1;
            }
            printf(",%.17g,%.17g,%.17g,%.17g", r.rotational_temperature, r.theta, r.a2_rot, r.cw2);
        }
        printf("\n");
    }
    return check(gdsmc_sim_destroy(&sim), "gdsmc_sim_destroy");
}
