// gdsmc.hpp: a small RAII wrapper over the C ABI of gdsmc (include/gdsmc.h). Header-only,
// C++17. Errors become gdsmc::Error exceptions carrying the status and the message.
#ifndef GDSMC_HPP
#define GDSMC_HPP

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "gdsmc.h"

namespace gdsmc {

// A failed gdsmc call: its status and message (from gdsmc_last_error).
class Error : public std::runtime_error {
public:
    Error(gdsmc_status status, const std::string &what)
        : std::runtime_error(what), status_(status) {}
    gdsmc_status status() const noexcept { return status_; }

private:
    gdsmc_status status_;
};

// Throws gdsmc::Error unless `s` is GDSMC_OK.
inline void check(gdsmc_status s, const char *call) {
    if (s == GDSMC_OK) return;
    std::string msg(gdsmc_last_error(nullptr, 0) + 1, '\0');
    gdsmc_last_error(&msg[0], msg.size());
    msg.pop_back();
    throw Error(s, std::string(call) + ": " + msg);
}

// The defaults (GRW Example 3), to be modified field by field.
inline gdsmc_config default_config() {
    gdsmc_config c;
    check(gdsmc_config_default(&c), "gdsmc_config_default");
    return c;
}

// A configuration from scene TOML text.
inline gdsmc_config config_from_toml(const std::string &toml) {
    gdsmc_config c;
    check(gdsmc_config_from_toml(toml.c_str(), &c), "gdsmc_config_from_toml");
    return c;
}

// Owns a heap simulation; destroyed with the object. Movable, not copyable; not thread-safe.
class Simulation {
public:
    explicit Simulation(const gdsmc_config &c) { check(gdsmc_sim_create(&c, &sim_), "gdsmc_sim_create"); }
    ~Simulation() { gdsmc_sim_destroy(&sim_); }
    Simulation(const Simulation &) = delete;
    Simulation &operator=(const Simulation &) = delete;
    Simulation(Simulation &&o) noexcept : sim_(std::exchange(o.sim_, nullptr)) {}
    Simulation &operator=(Simulation &&o) noexcept {
        if (this != &o) {
            gdsmc_sim_destroy(&sim_);
            sim_ = std::exchange(o.sim_, nullptr);
        }
        return *this;
    }

    // Runs to time t and returns the observables there.
    gdsmc_observables advance(double t) {
        gdsmc_observables o;
        check(gdsmc_sim_advance(sim_, t, &o), "gdsmc_sim_advance");
        return o;
    }
    gdsmc_observables observables() const {
        gdsmc_observables o;
        check(gdsmc_sim_observables(sim_, &o), "gdsmc_sim_observables");
        return o;
    }
    std::size_t size() const {
        uint64_t n = 0;
        check(gdsmc_sim_particle_count(sim_, &n), "gdsmc_sim_particle_count");
        return static_cast<std::size_t>(n);
    }
    // Velocities as x0, y0, z0, x1, ...
    std::vector<double> velocities() const {
        std::vector<double> v(3 * size());
        check(gdsmc_sim_get_velocities(sim_, v.data(), v.size()), "gdsmc_sim_get_velocities");
        return v;
    }
    // The particles' weights (1 each unless config.scheme = GDSMC_SCHEME_WEIGHTED, whose
    // number of particles, size(), changes as it runs).
    std::vector<double> weights() const {
        std::vector<double> w(size());
        check(gdsmc_sim_get_weights(sim_, w.data(), w.size()), "gdsmc_sim_get_weights");
        return w;
    }
    void set_velocities(const std::vector<double> &v) {
        check(gdsmc_sim_set_velocities(sim_, v.data(), v.size()), "gdsmc_sim_set_velocities");
    }
    void reseed(uint64_t seed) { check(gdsmc_sim_reseed(sim_, seed), "gdsmc_sim_reseed"); }
    // The most work one advance may ask for (events and particle updates; default 1e12).
    void set_work_limit(double limit) {
        check(gdsmc_sim_set_work_limit(sim_, limit), "gdsmc_sim_set_work_limit");
    }
    gdsmc_sim *raw() noexcept { return sim_; }

private:
    gdsmc_sim *sim_ = nullptr;
};

// One reference curve of a configuration at the asked times (gdsmc_reference_get): its
// column name, the observable it is of, its paper and equation, its kind
// (GDSMC_REFERENCE_MEAN_AT_N, _LIMIT, _APPROXIMATION), its values, and how many of them its
// arithmetic cannot hold at (NaN there: flagged, not thrown).
struct Reference {
    std::string name, of, source;
    uint32_t kind = 0;
    std::vector<double> values;
    std::size_t not_computable = 0;
};

namespace detail {
inline Reference reference(gdsmc_status s, const gdsmc_reference &r, std::vector<double> v,
                           const char *call) {
    if (s != GDSMC_NOT_COMPUTABLE) check(s, call);
    return Reference{r.name, r.of, r.source, r.kind, std::move(v), r.not_computable};
}
}  // namespace detail

// Every reference that holds for `c` observed at `times`, as `gdsmc run` writes them beside its
// means (the same code: equal to its columns to the bit).
inline std::vector<Reference> references(const gdsmc_config &c, const std::vector<double> &times) {
    std::size_t count = 0;
    check(gdsmc_reference_count(&c, times.data(), times.size(), &count), "gdsmc_reference_count");
    std::vector<Reference> out;
    for (std::size_t k = 0; k < count; ++k) {
        gdsmc_reference r;
        std::vector<double> v(times.size());
        gdsmc_status s = gdsmc_reference_get(&c, times.data(), times.size(), k, &r, v.data());
        out.push_back(detail::reference(s, r, std::move(v), "gdsmc_reference_get"));
    }
    return out;
}

// The reference named `name` (`T_mean_n`, `T_exact`, ...); throws GDSMC_NOT_FOUND when none of
// that name holds for `c`.
inline Reference reference(const gdsmc_config &c, const std::vector<double> &times,
                           const std::string &name) {
    gdsmc_reference r;
    std::vector<double> v(times.size());
    gdsmc_status s =
        gdsmc_reference_find(&c, times.data(), times.size(), name.c_str(), &r, v.data());
    return detail::reference(s, r, std::move(v), "gdsmc_reference_find");
}

// An ensemble mean with the 99.9% interval `gdsmc run` reports (gdsmc_mean_add,
// gdsmc_mean_interval): add one value per ensemble, then read {mean, half-width}.
class Mean {
public:
    void add(double x) { check(gdsmc_mean_add(&m_, x), "gdsmc_mean_add"); }
    std::pair<double, double> interval() const {
        double mean = 0, half = 0;
        check(gdsmc_mean_interval(&m_, &mean, &half), "gdsmc_mean_interval");
        return {mean, half};
    }
    uint64_t count() const noexcept { return m_.count; }

private:
    gdsmc_mean m_{};
};

}  // namespace gdsmc

#endif  // GDSMC_HPP
