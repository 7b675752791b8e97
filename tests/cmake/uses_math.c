/*
 * A user's numerical program as the README's CMake lines link it (gdsmc::gdsmc alone): it calls
 * the C math library beside gdsmc (values read at run time, so the compiler cannot fold the
 * calls away). The link failed with `sqrt` and `exp` undefined until gdsmc::gdsmc carried libm.
 */
#include <math.h>
#include <stdio.h>
#include "gdsmc.h"

int main(int argc, char **argv) {
    (void)argv;
    volatile double x = 2.0 + argc;
    gdsmc_mean acc = {0};
    if (gdsmc_mean_add(&acc, sqrt(x)) != GDSMC_OK || gdsmc_mean_add(&acc, exp(-x)) != GDSMC_OK)
        return 1;
    double mean, half;
    if (gdsmc_mean_interval(&acc, &mean, &half) != GDSMC_OK) return 1;
    printf("gdsmc %s: mean %.6f +- %.6f\n", gdsmc_version(), mean, half);
    return !(mean > 0.0 && half > 0.0);
}
