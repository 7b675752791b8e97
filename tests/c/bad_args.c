/*
 * Every kind of bad argument to the C ABI, with the status each must give, and the
 * allocation-free variant end to end. Run under valgrind in CI (no errors, no leaks).
 * Prints "N passed, M failed" and exits non-zero on any failure.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "gdsmc.h"

static int passed = 0, failed = 0;

#define EXPECT(cond, ...)                                        \
    do {                                                         \
        if (cond) {                                              \
            passed++;                                            \
        } else {                                                 \
            failed++;                                            \
            fprintf(stderr, "FAIL %s:%d: ", __FILE__, __LINE__); \
            fprintf(stderr, __VA_ARGS__);                        \
            fprintf(stderr, "\n");                               \
        }                                                        \
    } while (0)

static char msg[1024];

/* Status equals `want` and the last-error message contains `needle`. */
static void expect_status(gdsmc_status got, gdsmc_status want, const char *needle, int line) {
    gdsmc_last_error(msg, sizeof msg);
    if (got == want && (needle == NULL || strstr(msg, needle) != NULL)) {
        passed++;
    } else {
        failed++;
        fprintf(stderr, "FAIL line %d: status %d (want %d), message \"%s\" (want \"%s\")\n", line,
                (int)got, (int)want, msg, needle ? needle : "");
    }
}
#define STATUS(call, want, needle) expect_status((call), (want), (needle), __LINE__)

static gdsmc_config base(void) {
    gdsmc_config c;
    gdsmc_config_default(&c);
    c.n = 64;
    return c;
}

static void config_errors(void) {
    gdsmc_sim *sim = (gdsmc_sim *)0x1;
    STATUS(gdsmc_config_default(NULL), GDSMC_NULL_POINTER, "`out` is NULL");
    STATUS(gdsmc_sim_create(NULL, &sim), GDSMC_NULL_POINTER, "`config` is NULL");
    EXPECT(sim == NULL, "create must clear *out on failure");
    gdsmc_config c = base();
    STATUS(gdsmc_sim_create(&c, NULL), GDSMC_NULL_POINTER, "`out` is NULL");

    c = base(); c.n = 1;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.n must be >= 2");
    c = base(); c.stream = GDSMC_MAX_STREAM + 1;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.stream = 1048577 is above 2^20");
    c = base(); c.kernel = 7;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.kernel = 7");
    c = base(); c.drive = 99;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.drive = 99");
    c = base(); c.scheme = 99;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.scheme = 99");
    c = base(); c.scheme = GDSMC_SCHEME_WEIGHTED; c.scheme_params[GDSMC_WEIGHTED_CAPACITY] = 1.0;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.scheme_params[3]");
    c = base(); c.scheme = GDSMC_SCHEME_WEIGHTED; c.scheme_params[GDSMC_WEIGHTED_TARGET] = 5.0;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT,
           "config.scheme_params[4] must be below capacity");
    c = base(); c.dimension = 4;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT,
           "config.dimension must be 2 (disks) or 3 (spheres), got 4");
    c = base(); c.dimension = 2; c.drive = GDSMC_DRIVE_HOST_MEDIUM; c.background_drift[2] = 1.0;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT,
           "config.background_drift must lie in the plane (z = 0) for disks");
    c = base(); c.restitution = 1.5;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.restitution");
    c = base(); c.restitution = 0.0;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.restitution");
    c = base(); c.restitution = NAN;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.restitution");
    c = base(); c.beta = -1.0;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.beta");
    /* A declared drive's parameters in drive_params, named by their place. */
    c = base(); c.drive = GDSMC_DRIVE_LANGEVIN; c.drive_params[GDSMC_LANGEVIN_FRICTION] = -1.0;
    c.drive_params[GDSMC_LANGEVIN_TEMPERATURE] = 1.0;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT,
           "config.drive_params[0] must be > 0, got -1");
    c = base(); c.drive = GDSMC_DRIVE_LANGEVIN; c.drive_params[GDSMC_LANGEVIN_FRICTION] = 0.5;
    c.drive_params[GDSMC_LANGEVIN_TEMPERATURE] = -2.0;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT,
           "config.drive_params[1] must be >= 0, got -2");
    c = base(); c.gamma = 0.0;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.gamma");
    c = base(); c.kernel = GDSMC_KERNEL_VHS; c.kernel_params[GDSMC_VHS_LAMBDA] = 2.0;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.kernel_params[0]");
    c = base(); c.temperature = INFINITY;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.temperature");
    c = base(); c.drift[1] = NAN;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.drift");

    /* A misaligned config pointer. */
    unsigned char raw[sizeof(gdsmc_config) + 16];
    gdsmc_config *odd = (gdsmc_config *)(raw + 1);
    STATUS(gdsmc_sim_create(odd, &sim), GDSMC_MISALIGNED, "not aligned");
}

static void toml_errors(void) {
    gdsmc_config c;
    STATUS(gdsmc_config_from_toml(NULL, &c), GDSMC_NULL_POINTER, "`toml` is NULL");
    STATUS(gdsmc_config_from_toml("[collisions\n", &c), GDSMC_PARSE_ERROR, "line 1");
    const char *bad_alpha =
        "[collisions]\nkernel = \"maxwell\"\nrestitution = 2.0\n[observe]\nt_end = 1.0\n";
    STATUS(gdsmc_config_from_toml(bad_alpha, &c), GDSMC_INVALID_ARGUMENT,
           "<toml>:3: `collisions.restitution` must lie in (0, 1]");
    const char *unknown = "[collisions]\nkernel = \"maxwell\"\nrestitution = 0.5\n[observe]\nt_end = 1.0\nfoo = 1\n";
    STATUS(gdsmc_config_from_toml(unknown, &c), GDSMC_PARSE_ERROR, "unknown field `foo`");
    /* A kernel's keys are its declaration's: one it does not have is named with those it has. */
    const char *not_its = "[collisions]\nkernel = \"maxwell\"\nrestitution = 0.5\nlambda = 0.5\n[observe]\nt_end = 1.0\n";
    STATUS(gdsmc_config_from_toml(not_its, &c), GDSMC_INVALID_ARGUMENT,
           "<toml>:4: `collisions.lambda` is not a key of [collisions] with kernel = \"maxwell\" (its keys: kernel, gamma, c, diameter, density, restitution, impact_speed_law, pair_restitution)");
    const char *good =
        "[particles]\nn = 100\n[collisions]\nkernel = \"hard-spheres\"\ngamma = 4.0\nrestitution = 0.5\n"
        "[drive]\nkind = \"white-noise\"\nbeta = 0.125\n[observe]\nt_end = 2.0\n[run]\nseed = 9\n";
    STATUS(gdsmc_config_from_toml(good, &c), GDSMC_OK, "");
    EXPECT(c.n == 100 && c.kernel == GDSMC_KERNEL_HARD_SPHERES && c.beta == 0.125 && c.seed == 9 &&
               c.drive == GDSMC_DRIVE_WHITE_NOISE && c.restitution == 0.5 && c.gamma == 4.0,
           "TOML fields not carried over");
}

static void handle_errors(void) {
    gdsmc_config c = base();
    gdsmc_sim *sim = NULL;
    gdsmc_observables o;
    STATUS(gdsmc_sim_advance(NULL, 1.0, &o), GDSMC_NULL_POINTER, "`sim` is NULL");
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_OK, "");
    STATUS(gdsmc_sim_advance(sim, 0.5, &o), GDSMC_OK, "");
    EXPECT(o.t == 0.5 && o.temperature > 0.0 && o.collisions > 0, "advance gave t=%g T=%g", o.t,
           o.temperature);
    STATUS(gdsmc_sim_advance(sim, 0.25, &o), GDSMC_TIME_BACKWARDS, "before the current time");
    STATUS(gdsmc_sim_advance(sim, NAN, &o), GDSMC_TIME_BACKWARDS, "");
    STATUS(gdsmc_sim_advance(sim, 0.75, NULL), GDSMC_OK, "");
    STATUS(gdsmc_sim_observables(sim, NULL), GDSMC_NULL_POINTER, "`out` is NULL");

    uint64_t n = 0;
    STATUS(gdsmc_sim_particle_count(sim, &n), GDSMC_OK, "");
    EXPECT(n == 64, "particle count %llu", (unsigned long long)n);
    double v[3 * 64];
    STATUS(gdsmc_sim_get_velocities(sim, v, 3 * 64 - 1), GDSMC_BUFFER_TOO_SMALL, "len");
    STATUS(gdsmc_sim_get_velocities(sim, NULL, 3 * 64), GDSMC_NULL_POINTER, "`out` is NULL");
    STATUS(gdsmc_sim_get_velocities(sim, (double *)((char *)v + 1), 3 * 64 - 1), GDSMC_MISALIGNED, "");
    STATUS(gdsmc_sim_get_velocities(sim, v, 3 * 64), GDSMC_OK, "");

    /* Non-finite input is refused and leaves the state unchanged. */
    double w[3 * 64];
    memcpy(w, v, sizeof v);
    w[17] = NAN;
    STATUS(gdsmc_sim_set_velocities(sim, w, 3 * 64), GDSMC_INVALID_ARGUMENT, "velocities[17]");
    double u[3 * 64];
    gdsmc_sim_get_velocities(sim, u, 3 * 64);
    EXPECT(memcmp(u, v, sizeof v) == 0, "refused set_velocities changed the state");
    /* Finite but so large that the moments would overflow: refused before storing (it once
     * stored them, then reported GDSMC_NON_FINITE with the handle broken). */
    memcpy(w, v, sizeof v);
    w[5] = 1e200;
    STATUS(gdsmc_sim_set_velocities(sim, w, 3 * 64), GDSMC_INVALID_ARGUMENT, "velocities too large");
    gdsmc_sim_get_velocities(sim, u, 3 * 64);
    EXPECT(memcmp(u, v, sizeof v) == 0, "refused set_velocities changed the state");
    STATUS(gdsmc_sim_observables(sim, &o), GDSMC_OK, "");
    /* A valid write: all zero velocities give zero temperature. */
    memset(w, 0, sizeof w);
    STATUS(gdsmc_sim_set_velocities(sim, w, 3 * 64), GDSMC_OK, "");
    STATUS(gdsmc_sim_observables(sim, &o), GDSMC_OK, "");
    EXPECT(o.temperature == 0.0 && o.t == 0.75, "after set: T=%g t=%g", o.temperature, o.t);
    STATUS(gdsmc_sim_reseed(sim, 5), GDSMC_OK, "");
    STATUS(gdsmc_sim_advance(sim, 1.0, &o), GDSMC_OK, "");
    EXPECT(o.temperature > 0.0, "white noise must heat a cold gas");

    STATUS(gdsmc_sim_destroy(&sim), GDSMC_OK, "");
    EXPECT(sim == NULL, "destroy must clear the handle");
    STATUS(gdsmc_sim_destroy(&sim), GDSMC_OK, ""); /* NULL handle: no-op */
    STATUS(gdsmc_sim_destroy(NULL), GDSMC_NULL_POINTER, "");
    STATUS(gdsmc_sim_advance(sim, 2.0, &o), GDSMC_NULL_POINTER, "");
}

static void allocation_free(void) {
    size_t bytes = 0, align = 0;
    STATUS(gdsmc_sim_footprint(1, &bytes, &align), GDSMC_INVALID_ARGUMENT, "n must be >= 2");
    STATUS(gdsmc_sim_footprint(64, NULL, &align), GDSMC_NULL_POINTER, "");
    STATUS(gdsmc_sim_footprint(UINT64_MAX, &bytes, &align), GDSMC_INVALID_ARGUMENT, "too large");
    gdsmc_config c = base();
    c.n = 2048;
    STATUS(gdsmc_sim_footprint(c.n, &bytes, &align), GDSMC_OK, "");
    EXPECT(bytes >= 32 * c.n && align >= 32 && (align & (align - 1)) == 0, "footprint %zu align %zu",
           bytes, align);

    unsigned char *mem = aligned_alloc(align, bytes + align);
    gdsmc_sim *sim = NULL;
    STATUS(gdsmc_sim_init_in(NULL, bytes, &c, &sim), GDSMC_NULL_POINTER, "`memory` is NULL");
    STATUS(gdsmc_sim_init_in(mem + 8, bytes, &c, &sim), GDSMC_MISALIGNED, "not aligned");
    STATUS(gdsmc_sim_init_in(mem, bytes - 1, &c, &sim), GDSMC_BUFFER_TOO_SMALL, "gdsmc_sim_footprint");
    STATUS(gdsmc_sim_init_in(mem, bytes, &c, &sim), GDSMC_OK, "");
    EXPECT((void *)sim == (void *)mem, "handle must live in the caller's memory");

    /* GRW Example 3 to t = 8 in caller memory: T near 8/3 (one ensemble of 2048 particles:
     * relative standard deviation about 2%, so 15% is a loose sanity bound). */
    gdsmc_observables o;
    STATUS(gdsmc_sim_advance(sim, 8.0, &o), GDSMC_OK, "");
    EXPECT(fabs(o.temperature - 8.0 / 3.0) < 0.15 * 8.0 / 3.0, "T(8) = %g", o.temperature);

    gdsmc_sim *copy = sim;
    STATUS(gdsmc_sim_destroy(&sim), GDSMC_OK, "");
    EXPECT(sim == NULL, "destroy must clear the handle");
    STATUS(gdsmc_sim_advance(copy, 9.0, &o), GDSMC_INVALID_HANDLE, "not a live simulation");
    STATUS(gdsmc_sim_destroy(&copy), GDSMC_INVALID_HANDLE, "");
    free(mem);
}

static void schemes_and_host_medium(void) {
    gdsmc_config c = base();
    gdsmc_sim *sim = NULL;
    gdsmc_observables o;
    c.scheme = 7;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.scheme = 7");
    c = base(); c.scheme = GDSMC_SCHEME_STRANG; c.dt = 0.0;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.dt");
    c.dt = 0.25;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_OK, "");
    STATUS(gdsmc_sim_advance(sim, 0.3, &o), GDSMC_INVALID_ARGUMENT, "multiple of config.dt");
    STATUS(gdsmc_sim_advance(sim, 0.5, &o), GDSMC_OK, "");
    EXPECT(o.t == 0.5, "strang t = %g", o.t);
    STATUS(gdsmc_sim_destroy(&sim), GDSMC_OK, "");
    /* A step longer than the advance takes no step: refused, not the start's state as t = 8. */
    c.dt = 1e300;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_OK, "");
    STATUS(gdsmc_sim_advance(sim, 8.0, &o), GDSMC_INVALID_ARGUMENT, "at least one step");
    STATUS(gdsmc_sim_destroy(&sim), GDSMC_OK, "");

    c = base(); c.drive = GDSMC_DRIVE_HOST_MEDIUM; c.background_kernel = 5;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.background_kernel = 5");
    c.background_kernel = GDSMC_BACKGROUND_HARD_SPHERES; c.background_density = -1.0;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.background_density");
    /* BRS Example 2 (Maxwell kernels): the bulk velocity relaxes towards u^B = (0, 1, 0) as
     * 1 - exp(-2 pi t); at t = 1 that is 0.998, one ensemble of 2048 grains is within 0.1. */
    c = base(); c.n = 2048; c.drive = GDSMC_DRIVE_HOST_MEDIUM;
    c.kernel = GDSMC_KERNEL_MAXWELL; c.gamma = 1.0; c.c = 0.125;
    c.background_kernel = GDSMC_BACKGROUND_MAXWELL; c.background_drift[1] = 1.0;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_OK, "");
    STATUS(gdsmc_sim_advance(sim, 1.0, &o), GDSMC_OK, "");
    EXPECT(fabs(o.bulk_velocity[1] - 1.0) < 0.1, "V_y(1) = %g", o.bulk_velocity[1]);
    STATUS(gdsmc_sim_destroy(&sim), GDSMC_OK, "");
}

/* The time-stepped scheme and the impact-speed law: their rules come from the core's one
 * validation, with the C field's name. */
static void time_stepped_and_impact_law(void) {
    gdsmc_config c = base();
    gdsmc_sim *sim = NULL;
    gdsmc_observables o;
    c.scheme = GDSMC_SCHEME_TIME_STEPPED; c.step_factor = 0.01;
    /* Every kernel takes it (Bird's form for Maxwell molecules: no candidate is fictitious). */
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_OK, "");
    STATUS(gdsmc_sim_advance(sim, 0.5, &o), GDSMC_OK, "");
    EXPECT(o.t == 0.5 && o.collisions > 0 && o.fictitious == 0,
           "time-stepped Maxwell t = %g, %llu collisions", o.t, (unsigned long long)o.collisions);
    STATUS(gdsmc_sim_destroy(&sim), GDSMC_OK, "");
    c.kernel = GDSMC_KERNEL_HARD_SPHERES; c.step_factor = 0.0;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.step_factor must be > 0, got 0");
    c.step_factor = 0.01;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_OK, "");
    STATUS(gdsmc_sim_advance(sim, 0.5, &o), GDSMC_OK, "");
    EXPECT(o.t == 0.5 && o.collisions > 0, "time-stepped t = %g, %llu collisions", o.t,
           (unsigned long long)o.collisions);
    STATUS(gdsmc_sim_destroy(&sim), GDSMC_OK, "");

    c = base(); c.restitution_law = 5;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.restitution_law = 5");
    c.restitution_law = GDSMC_RESTITUTION_IMPACT_SPEED; c.impact_beta0 = -0.1;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.impact_beta0 must be >= 0, got -0.1");
    c.impact_beta0 = 0.1; c.impact_delta = NAN;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.impact_delta must be a finite number");
    c.impact_delta = 0.2;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_OK, "");
    STATUS(gdsmc_sim_advance(sim, 0.5, &o), GDSMC_OK, "");
    STATUS(gdsmc_sim_destroy(&sim), GDSMC_OK, "");
}

static void last_error_buffer(void) {
    gdsmc_config_default(NULL);
    size_t need = gdsmc_last_error(NULL, 0);
    EXPECT(need == strlen("`out` is NULL"), "need %zu", need);
    char small[4] = {'x', 'x', 'x', 'x'};
    size_t got = gdsmc_last_error(small, sizeof small);
    EXPECT(got == need && small[3] == '\0' && strncmp(small, "`ou", 3) == 0, "truncation");
    gdsmc_config c;
    gdsmc_config_default(&c);
    EXPECT(gdsmc_last_error(NULL, 0) == 0, "success clears the message");
}

/* Rough particles: their refusals by field, their footprint (room for the spins), a run in
 * caller memory, and the rotation readers refusing a smooth gas. */
static void rough_particles(void) {
    gdsmc_config c = base();
    c.n = 512;
    c.kernel = GDSMC_KERNEL_HARD_SPHERES;
    c.rough = 1;
    c.tangential_restitution = 1.5;
    gdsmc_sim *sim = NULL;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT,
           "config.tangential_restitution must lie in [-1, 1], got 1.5");
    c.tangential_restitution = 0.0;
    c.inertia = 0.9;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.inertia must lie in (0, 2/3]");
    c.dimension = 2;
    c.inertia = 1.2;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT, "config.inertia must lie in (0, 1] for disks");
    c.dimension = 3;
    c.inertia = 0.4;
    /* The thermostat acts on translation; rotational noise beside it is refused. */
    c.drive = GDSMC_DRIVE_GAUSSIAN;
    c.rotation_noise = 0.5;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_INVALID_ARGUMENT,
           "config.rotation_noise takes only no drive or white noise on translation beside it");
    c.rotation_noise = 0.0;
    c.drive = GDSMC_DRIVE_WHITE_NOISE;

    size_t smooth = 0, bytes = 0, align = 0;
    STATUS(gdsmc_sim_footprint(c.n, &smooth, &align), GDSMC_OK, "");
    STATUS(gdsmc_config_footprint(&c, &bytes, &align), GDSMC_OK, "");
    EXPECT(bytes == smooth + 32 * c.n, "rough footprint %zu, smooth %zu", bytes, smooth);
    unsigned char *mem = aligned_alloc(align, bytes);
    STATUS(gdsmc_sim_init_in(mem, smooth, &c, &sim), GDSMC_BUFFER_TOO_SMALL, "gdsmc_config_footprint");
    STATUS(gdsmc_sim_init_in(mem, bytes, &c, &sim), GDSMC_OK, "");
    gdsmc_observables o;
    gdsmc_rotation_observables r;
    STATUS(gdsmc_sim_advance(sim, 1.0, &o), GDSMC_OK, "");
    STATUS(gdsmc_sim_rotation(sim, &r), GDSMC_OK, "");
    EXPECT(r.translational_temperature == o.temperature_bulk && r.rotational_temperature > 0.0 &&
               r.theta == r.rotational_temperature / r.translational_temperature,
           "rotation: T_tr %g (T_bulk %g), T_rot %g, theta %g", r.translational_temperature,
           o.temperature_bulk, r.rotational_temperature, r.theta);
    double *w = malloc(3 * c.n * sizeof *w);
    STATUS(gdsmc_sim_get_rim_velocities(sim, w, 3 * c.n - 1), GDSMC_BUFFER_TOO_SMALL, "");
    STATUS(gdsmc_sim_get_rim_velocities(sim, w, 3 * c.n), GDSMC_OK, "");
    double s = 0.0;
    for (uint64_t i = 0; i < 3 * c.n; i++) s += w[i] * w[i];
    EXPECT(fabs(c.inertia * s / (3.0 * c.n) - r.rotational_temperature) <=
               1e-12 * r.rotational_temperature,
           "kappa <|w|^2>/3 = %g, T_rot %g", c.inertia * s / (3.0 * c.n), r.rotational_temperature);
    STATUS(gdsmc_sim_destroy(&sim), GDSMC_OK, "");

    c.rough = 0;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_OK, "");
    STATUS(gdsmc_sim_rotation(sim, &r), GDSMC_INVALID_ARGUMENT, "smooth");
    STATUS(gdsmc_sim_get_rim_velocities(sim, w, 3 * c.n), GDSMC_INVALID_ARGUMENT, "smooth");
    STATUS(gdsmc_sim_destroy(&sim), GDSMC_OK, "");
    free(w);
    free(mem);
}

/* Work far beyond what a call can mean is refused before anything runs, the state unchanged:
 * the C ABI's caller gets no endless call (the fuzzer once set one velocity of a hard-sphere
 * gas to 4.7e18, and an advance by 0.01 then asked for about 1e17 events). */
static void work_limit(void) {
    gdsmc_config c = base();
    c.kernel = GDSMC_KERNEL_HARD_SPHERES;
    c.drive = GDSMC_DRIVE_NONE;
    gdsmc_sim *sim = NULL;
    gdsmc_observables o;
    STATUS(gdsmc_sim_create(&c, &sim), GDSMC_OK, "");
    STATUS(gdsmc_sim_advance(sim, 0.5, &o), GDSMC_OK, "");
    double v[3 * 64], u[3 * 64], w[3 * 64];
    STATUS(gdsmc_sim_get_velocities(sim, v, 3 * 64), GDSMC_OK, "");

    /* A time 1e15 ahead: about 1e17 candidates at this gas's rate. */
    STATUS(gdsmc_sim_advance(sim, 1e15, &o), GDSMC_TOO_MUCH_WORK, "gdsmc_sim_set_work_limit");
    gdsmc_sim_get_velocities(sim, u, 3 * 64);
    EXPECT(memcmp(u, v, sizeof v) == 0, "a refused advance changed the velocities");
    STATUS(gdsmc_sim_observables(sim, &o), GDSMC_OK, "");
    EXPECT(o.t == 0.5, "a refused advance moved the time to %g", o.t);

    /* One velocity of 1e30 (its moments stay finite): a step of 0.01 is refused. */
    memcpy(w, v, sizeof v);
    w[5] = 1e30;
    STATUS(gdsmc_sim_set_velocities(sim, w, 3 * 64), GDSMC_OK, "");
    STATUS(gdsmc_sim_advance(sim, 0.51, &o), GDSMC_TOO_MUCH_WORK, "per unit time now");
    STATUS(gdsmc_sim_set_velocities(sim, v, 3 * 64), GDSMC_OK, "");
    STATUS(gdsmc_sim_advance(sim, 0.51, &o), GDSMC_OK, "");

    /* The limit is the caller's: positive (INFINITY for none). */
    STATUS(gdsmc_sim_set_work_limit(sim, 0.0), GDSMC_INVALID_ARGUMENT, "must be positive");
    STATUS(gdsmc_sim_set_work_limit(sim, NAN), GDSMC_INVALID_ARGUMENT, "must be positive");
    STATUS(gdsmc_sim_set_work_limit(NULL, 1.0), GDSMC_NULL_POINTER, "`sim` is NULL");
    STATUS(gdsmc_sim_set_work_limit(sim, 1.0), GDSMC_OK, "");
    STATUS(gdsmc_sim_advance(sim, 1.0, &o), GDSMC_TOO_MUCH_WORK, "above the limit 1.0e0");
    STATUS(gdsmc_sim_set_work_limit(sim, INFINITY), GDSMC_OK, "");
    STATUS(gdsmc_sim_advance(sim, 1.0, &o), GDSMC_OK, "");
    EXPECT(o.t == 1.0 && o.collisions > 0, "advance after the limit was lifted: t=%g", o.t);
    STATUS(gdsmc_sim_destroy(&sim), GDSMC_OK, "");
}

int main(void) {
    printf("gdsmc %s C ABI checks\n", gdsmc_version());
    config_errors();
    toml_errors();
    handle_errors();
    work_limit();
    allocation_free();
    schemes_and_host_medium();
    time_stepped_and_impact_law();
    last_error_buffer();
    rough_particles();
    printf("%d passed, %d failed\n", passed, failed);
    return failed != 0;
}
