/*
 * The C ABI's references are the command's columns: this program reads a scene file
 * (gdsmc_config_from_toml), sets n to the second argument when one is given (the command's
 * --n), reads the observation times from standard input (one per line, as strtod reads the
 * command's observables.csv) and prints, per time, every reference that holds for the
 * configuration (gdsmc_reference_count, gdsmc_reference_get) with 17 significant digits:
 *   t,NAME1,NAME2,...
 * A reference not computable at some times prints NaN there and is named on standard error.
 * tests/c/references_as_command.sh compares the columns with `gdsmc run`'s bit for bit.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include "gdsmc.h"
#include "scene_file.h"

int main(int argc, char **argv) {
    if (argc != 2 && argc != 3) {
        fprintf(stderr, "usage: %s SCENE.toml [N] < times\n", argv[0]);
        return 2;
    }
    gdsmc_config cfg;
    int bad = config_of(argv[1], &cfg);
    if (bad) return bad;
    gdsmc_status s;
    if (argc == 3) cfg.n = strtoull(argv[2], NULL, 10);
    size_t cap = 64, nt = 0;
    double *times = malloc(cap * sizeof *times);
    char line[128];
    while (times && fgets(line, sizeof line, stdin)) {
        if (nt == cap) {
            double *more = realloc(times, 2 * cap * sizeof *times);
            if (!more) break;
            times = more;
            cap *= 2;
        }
        times[nt++] = strtod(line, NULL);
    }
    size_t count = 0;
    if (!times || check(gdsmc_reference_count(&cfg, times, nt, &count), "gdsmc_reference_count")) {
        free(times);
        return 1;
    }
    double *values = malloc((count ? count : 1) * nt * sizeof *values);
    gdsmc_reference *refs = malloc((count ? count : 1) * sizeof *refs);
    int failed = !values || !refs;
    for (size_t k = 0; k < count && !failed; k++) {
        s = gdsmc_reference_get(&cfg, times, nt, k, &refs[k], values + k * nt);
        if (s == GDSMC_NOT_COMPUTABLE) {
            fprintf(stderr, "%s: not computable at %zu times\n", refs[k].name,
                    refs[k].not_computable);
        } else {
            failed = check(s, "gdsmc_reference_get");
        }
    }
    if (!failed) {
        printf("t");
        for (size_t k = 0; k < count; k++) printf(",%s", refs[k].name);
        printf("\n");
        for (size_t i = 0; i < nt; i++) {
            printf("%.17g", times[i]);
            for (size_t k = 0; k < count; k++) printf(",%.17g", values[k * nt + i]);
            printf("\n");
        }
    }
    free(values);
    free(refs);
    free(times);
    return failed;
}
