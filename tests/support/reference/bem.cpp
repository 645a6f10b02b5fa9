#include "reference/bem.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "reference/quadrature.hpp"

namespace mdr::reference {
namespace {

using std::numbers::pi;

// Dense row-major square matrix.
struct Matrix {
    std::size_t size = 0;
    std::vector<double> data;
    double& operator()(std::size_t i, std::size_t j) { return data[i * size + j]; }
    double operator()(std::size_t i, std::size_t j) const { return data[i * size + j]; }
};

// C_ij: displacement at the centre of ring i under unit pressure on ring j (unit shear modulus).
Matrix influence_matrix(std::size_t rings, double spacing) {
    Matrix c{rings, std::vector<double>(rings * rings)};
    for (std::size_t i = 0; i < rings; ++i) {
        const double r = (static_cast<double>(i) + 0.5) * spacing;
        double inner = 0.0;
        for (std::size_t j = 0; j < rings; ++j) {
            const double outer = uniform_disk_displacement(static_cast<double>(j + 1) * spacing, r);
            c(i, j) = outer - inner;
            inner = outer;
        }
    }
    return c;
}

// Doolittle LU without pivoting. Its leading k×k blocks factor the leading k×k block of the matrix, so one
// factorisation serves every contact disk (a prefix of the rings).
Matrix lu_without_pivoting(Matrix a) {
    const std::size_t n = a.size;
    for (std::size_t k = 0; k < n; ++k) {
        if (!(a(k, k) > 0.0))
            throw std::runtime_error("reference BEM: influence matrix pivot " + std::to_string(k) + " = " +
                                     std::to_string(a(k, k)) + ", expected > 0");
        for (std::size_t i = k + 1; i < n; ++i) {
            const double factor = a(i, k) / a(k, k);
            a(i, k) = factor;
            for (std::size_t j = k + 1; j < n; ++j) a(i, j) -= factor * a(k, j);
        }
    }
    return a;
}

// Solves the leading k×k system of the factorised matrix in place.
void solve_prefix(const Matrix& lu, std::size_t k, std::vector<double>& rhs) {
    for (std::size_t i = 0; i < k; ++i)
        for (std::size_t j = 0; j < i; ++j) rhs[i] -= lu(i, j) * rhs[j];
    for (std::size_t i = k; i-- > 0;) {
        for (std::size_t j = i + 1; j < k; ++j) rhs[i] -= lu(i, j) * rhs[j];
        rhs[i] /= lu(i, i);
    }
}

// Solves C_AA x = rhs for a contact set A that is not a disk, by Gaussian elimination with partial pivoting.
std::vector<double> solve_subsystem(const Matrix& c, const std::vector<std::size_t>& set, std::vector<double> rhs) {
    const std::size_t n = set.size();
    Matrix a{n, std::vector<double>(n * n)};
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) a(i, j) = c(set[i], set[j]);
    for (std::size_t k = 0; k < n; ++k) {
        std::size_t pivot = k;
        for (std::size_t i = k + 1; i < n; ++i)
            if (std::abs(a(i, k)) > std::abs(a(pivot, k))) pivot = i;
        if (pivot != k) {
            for (std::size_t j = 0; j < n; ++j) std::swap(a(k, j), a(pivot, j));
            std::swap(rhs[k], rhs[pivot]);
        }
        for (std::size_t i = k + 1; i < n; ++i) {
            const double factor = a(i, k) / a(k, k);
            for (std::size_t j = k; j < n; ++j) a(i, j) -= factor * a(k, j);
            rhs[i] -= factor * rhs[k];
        }
    }
    for (std::size_t i = n; i-- > 0;) {
        for (std::size_t j = i + 1; j < n; ++j) rhs[i] -= a(i, j) * rhs[j];
        rhs[i] /= a(i, i);
    }
    return rhs;
}

// w_k = (1/Δt) ∫_{kΔt}^{(k+1)Δt} J(s) ds, k = 0..steps−1: the weight of a pressure increment k steps back.
std::vector<double> creep_weights(const std::function<double(double)>& creep, double step, std::size_t steps) {
    std::vector<double> weights(steps);
    for (std::size_t k = 0; k < steps; ++k) {
        const double start = static_cast<double>(k) * step;
        weights[k] = integrate(creep, start, start + step, 1e-13) / step;
    }
    return weights;
}

}  // namespace

double uniform_disk_displacement(double disk_radius, double r) {
    if (r <= disk_radius) return disk_radius * std::comp_ellint_2(r / disk_radius) / pi;
    const double k = disk_radius / r;
    return r * (std::comp_ellint_2(k) - (1.0 - k * k) * std::comp_ellint_1(k)) / pi;
}

void BemOptions::validate() const {
    if (rings < 2) throw std::invalid_argument("reference bem.rings = " + std::to_string(rings) + ": must be >= 2");
    if (steps < 1) throw std::invalid_argument("reference bem.steps = " + std::to_string(steps) + ": must be >= 1");
    if (!(domain_radius > 0.0))
        throw std::invalid_argument("reference bem.domain_radius = " + std::to_string(domain_radius) +
                                    ": must be > 0");
}

BemResult solve_axisymmetric_bem(const std::function<double(double)>& gap, const std::function<double(double)>& creep,
                                 const PiecewiseLinear& depth, const BemOptions& options) {
    options.validate();
    depth.validate();
    const auto rings = static_cast<std::size_t>(options.rings);
    const auto steps = static_cast<std::size_t>(options.steps);
    const double spacing = options.domain_radius / static_cast<double>(rings);
    const double t0 = depth.times.front();
    const double step = (depth.times.back() - t0) / static_cast<double>(steps);

    const Matrix influence = influence_matrix(rings, spacing);
    const Matrix lu = lu_without_pivoting(influence);
    const std::vector<double> weights = creep_weights(creep, step, steps);
    std::vector<double> centre(rings);
    std::vector<double> gap_at(rings);
    for (std::size_t i = 0; i < rings; ++i) {
        centre[i] = (static_cast<double>(i) + 0.5) * spacing;
        gap_at[i] = gap(centre[i]);
    }
    double depth_scale = 0.0;
    for (double d : depth.values) depth_scale = std::max(depth_scale, std::abs(d));
    const double penetration_tol = 1e-12 * depth_scale;

    BemResult result;
    result.times.push_back(t0);
    result.depth.push_back(depth.value(t0));
    result.force.push_back(0.0);
    result.contact_radius.push_back(0.0);

    std::vector<std::vector<double>> increments;  // Δp_j over each past step
    std::vector<double> pressure(rings, 0.0);
    std::vector<char> in_contact(rings, 0);
    std::vector<double> memory(rings);
    std::vector<double> offset(rings);
    std::vector<double> displacement(rings);
    for (std::size_t n = 1; n <= steps; ++n) {
        const double t = t0 + static_cast<double>(n) * step;
        const double d = depth.value(t);
        // u_i = w_0 (C p^n)_i + offset_i with offset = C (Σ_{m<n} w_{n−m} Δp^m − w_0 p^{n−1}).
        for (std::size_t j = 0; j < rings; ++j) memory[j] = -weights[0] * pressure[j];
        for (std::size_t m = 1; m < n; ++m)
            for (std::size_t j = 0; j < rings; ++j) memory[j] += weights[n - m] * increments[m - 1][j];
        for (std::size_t i = 0; i < rings; ++i) {
            double sum = 0.0;
            for (std::size_t j = 0; j < rings; ++j) sum += influence(i, j) * memory[j];
            offset[i] = sum;
        }
        std::vector<double> next(rings, 0.0);
        bool settled = false;
        for (int iteration = 0; iteration < 200 && !settled; ++iteration) {
            std::vector<std::size_t> set;
            for (std::size_t i = 0; i < rings; ++i)
                if (in_contact[i]) set.push_back(i);
            std::vector<double> rhs(set.size());
            for (std::size_t a = 0; a < set.size(); ++a)
                rhs[a] = (d - gap_at[set[a]] - offset[set[a]]) / weights[0];
            const bool disk = set.empty() || set.back() + 1 == set.size();
            if (disk) solve_prefix(lu, set.size(), rhs);
            else rhs = solve_subsystem(influence, set, rhs);
            std::fill(next.begin(), next.end(), 0.0);
            for (std::size_t a = 0; a < set.size(); ++a) next[set[a]] = rhs[a];
            settled = true;
            for (std::size_t i = 0; i < rings; ++i) {
                if (in_contact[i]) {
                    if (next[i] < 0.0) {
                        in_contact[i] = 0;
                        settled = false;
                    }
                    continue;
                }
                double sum = 0.0;
                for (std::size_t j : set) sum += influence(i, j) * next[j];
                displacement[i] = weights[0] * sum + offset[i];
                if (displacement[i] < d - gap_at[i] - penetration_tol) {
                    in_contact[i] = 1;
                    settled = false;
                }
            }
        }
        if (!settled) throw std::runtime_error("reference BEM: active set did not settle at t = " + std::to_string(t));
        if (in_contact[rings - 1])
            throw std::runtime_error("reference BEM: contact reached the last ring at t = " + std::to_string(t) +
                                     "; increase domain_radius = " + std::to_string(options.domain_radius));
        std::vector<double> increment(rings);
        double force = 0.0;
        int outermost = -1;
        for (std::size_t j = 0; j < rings; ++j) {
            increment[j] = next[j] - pressure[j];
            force += 2.0 * pi * centre[j] * spacing * next[j];
            if (in_contact[j]) outermost = static_cast<int>(j);
        }
        increments.push_back(std::move(increment));
        pressure = next;
        result.times.push_back(t);
        result.depth.push_back(d);
        result.force.push_back(force);
        result.contact_radius.push_back(static_cast<double>(outermost + 1) * spacing);
    }
    return result;
}

}  // namespace mdr::reference
