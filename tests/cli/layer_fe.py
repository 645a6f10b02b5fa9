"""An independent finite-element model of the elastic layer on a rigid substrate (numpy/scipy only, no mdr code):
axisymmetric Taylor-Hood elements (biquadratic displacement, bilinear continuous pressure: the mixed u-p form, exact
incompressibility at nu = 0.5, stable by the inf-sup condition; for nu < 0.5 the same fields with the pressure's
own law div u + p / lambda = 0, lambda = 2 G nu / (1 - 2 nu), weakly: a block -M / lambda of the pressure mass matrix
M, the standard mixed form of the compressible body), a frictionless rigid sphere by an active set on the surface
nodes. Used by test_layer_fe.py to check mdr's layer (docs/theory.md section 4c)."""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

GAUSS_X = np.array([-np.sqrt(0.6), 0.0, np.sqrt(0.6)])
GAUSS_W = np.array([5.0, 8.0, 5.0]) / 9.0


def quadratic(x):
    """1-D quadratic Lagrange shape functions at nodes -1, 0, 1 and their derivatives."""
    return (np.array([0.5 * x * (x - 1.0), 1.0 - x * x, 0.5 * x * (x + 1.0)]),
            np.array([x - 0.5, -2.0 * x, x + 0.5]))


def linear(x):
    """1-D linear shape functions at nodes -1, 1."""
    return np.array([0.5 * (1.0 - x), 0.5 * (1.0 + x)])


def graded(length, fine_length, count_fine, count_coarse):
    """Vertices: uniform spacing fine_length/count_fine up to fine_length, then geometric to length."""
    uniform = np.linspace(0.0, fine_length, count_fine + 1)
    if count_coarse == 0:
        return uniform
    step = fine_length / count_fine
    # geometric growth q with sum_{k=1..n} step q^k = length - fine_length
    lo, hi = 1.0, 3.0
    for _ in range(200):
        q = 0.5 * (lo + hi)
        total = step * q * (q ** count_coarse - 1.0) / (q - 1.0)
        lo, hi = (q, hi) if total < length - fine_length else (lo, q)
    widths = step * q ** np.arange(1, count_coarse + 1)
    widths *= (length - fine_length) / widths.sum()
    return np.concatenate([uniform, fine_length + np.cumsum(widths)])


def graded_through(point, spacing, fine_length, length, count_coarse):
    """Vertices: uniform up to about fine_length with a spacing of at most `spacing` that puts a vertex on `point`
    (0 < point <= fine_length), then count_coarse geometric ones to `length` (graded)."""
    step = point / np.ceil(point / spacing)
    count_fine = int(np.ceil(fine_length / step - 1e-9))
    return graded(length, count_fine * step, count_fine, count_coarse)


class LayerFE:
    """Taylor-Hood Q9/Q4 (biquadratic displacement, bilinear continuous pressure) for the layer 0 <= z <= h,
    0 <= r <= r_max; bottom bonded (u = 0) or sliding (u_z = 0); u = 0 at r_max; u_r = 0 on the axis; the top surface
    z = h free except where an indenter prescribes u_z. Stress 2 G eps - p I with div u = 0 (nu = 0.5) or
    div u + p / lambda = 0 (nu < 0.5: sigma = 2 G eps + lambda div u I, the displacement form)."""

    def __init__(self, r_vertices, z_vertices, interface="bonded", shear_modulus=1.0, poisson_ratio=0.5):
        # 1 / lambda, lambda = 2 G nu / (1 - 2 nu) the Lame constant: 0 for the incompressible layer.
        compliance = (1.0 - 2.0 * poisson_ratio) / (2.0 * shear_modulus * poisson_ratio) if poisson_ratio < 0.5 else 0.0
        self.rv, self.zv = np.asarray(r_vertices, float), np.asarray(z_vertices, float)
        nr, nz = len(self.rv) - 1, len(self.zv) - 1
        # displacement nodes: vertices and midpoints
        self.r = np.empty(2 * nr + 1)
        self.r[0::2] = self.rv
        self.r[1::2] = 0.5 * (self.rv[:-1] + self.rv[1:])
        self.z = np.empty(2 * nz + 1)
        self.z[0::2] = self.zv
        self.z[1::2] = 0.5 * (self.zv[:-1] + self.zv[1:])
        self.mr, self.mz = len(self.r), len(self.z)
        n_u = self.mr * self.mz
        self.n_u = n_u
        self.n_p = len(self.rv) * len(self.zv)
        node = lambda i, j: i * self.mz + j  # noqa: E731
        pnode = lambda i, j: i * len(self.zv) + j  # noqa: E731
        rows, cols, vals = [], [], []
        for er in range(nr):
            r0, r1 = self.rv[er], self.rv[er + 1]
            for ez in range(nz):
                z0, z1 = self.zv[ez], self.zv[ez + 1]
                ke = np.zeros((18, 18))
                be = np.zeros((4, 18))
                me = np.zeros((4, 4))
                for gx, wx in zip(GAUSS_X, GAUSS_W):
                    nx, dx = quadratic(gx)
                    lx = linear(gx)
                    for gy, wy in zip(GAUSS_X, GAUSS_W):
                        ny, dy = quadratic(gy)
                        ly = linear(gy)
                        rr = 0.5 * (r0 + r1) + 0.5 * (r1 - r0) * gx
                        jr, jz = 0.5 * (r1 - r0), 0.5 * (z1 - z0)
                        weight = wx * wy * jr * jz * 2.0 * np.pi * rr
                        n = np.outer(nx, ny).ravel()               # local node (a, b) -> a * 3 + b
                        dn_dr = np.outer(dx, ny).ravel() / jr
                        dn_dz = np.outer(nx, dy).ravel() / jz
                        # strain rows: rr, zz, tt, rz (tensor); dofs: [ur_0, uz_0, ur_1, uz_1, ...]
                        bm = np.zeros((4, 18))
                        bm[0, 0::2] = dn_dr
                        bm[1, 1::2] = dn_dz
                        bm[2, 0::2] = n / rr
                        bm[3, 0::2] = 0.5 * dn_dz
                        bm[3, 1::2] = 0.5 * dn_dr
                        metric = np.diag([1.0, 1.0, 1.0, 2.0])
                        ke += weight * 2.0 * shear_modulus * bm.T @ metric @ bm
                        div = bm[0] + bm[1] + bm[2]
                        pn = np.outer(lx, ly).ravel()
                        be += -weight * np.outer(pn, div)
                        me += -weight * compliance * np.outer(pn, pn)
                unodes = [node(2 * er + a, 2 * ez + b) for a in range(3) for b in range(3)]
                udofs = np.array([[2 * k, 2 * k + 1] for k in unodes]).ravel()
                pdofs = 2 * n_u + np.array([pnode(er + a, ez + b) for a in range(2) for b in range(2)])
                rows.append(np.repeat(udofs, 18)); cols.append(np.tile(udofs, 18)); vals.append(ke.ravel())
                rows.append(np.repeat(pdofs, 18)); cols.append(np.tile(udofs, 4)); vals.append(be.ravel())
                rows.append(np.repeat(udofs, 4)); cols.append(np.tile(pdofs, 18)); vals.append(be.T.ravel())
                rows.append(np.repeat(pdofs, 4)); cols.append(np.tile(pdofs, 4)); vals.append(me.ravel())
        size = 2 * n_u + self.n_p
        self.matrix = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                                    shape=(size, size))
        fixed = []
        for j in range(self.mz):
            fixed.append(2 * node(0, j))                        # axis: u_r = 0
            fixed += [2 * node(self.mr - 1, j), 2 * node(self.mr - 1, j) + 1]   # far edge
        for i in range(self.mr):
            fixed.append(2 * node(i, 0) + 1)                    # substrate: u_z = 0
            if interface == "bonded":
                fixed.append(2 * node(i, 0))
        self.fixed = np.unique(fixed)
        self.top = np.array([2 * node(i, self.mz - 1) + 1 for i in range(self.mr)])  # u_z dofs of the surface

    def solve(self, prescribed_top):
        """prescribed_top: {surface node index i: u_z}. Returns (u, reactions at those u_z dofs)."""
        size = self.matrix.shape[0]
        known = np.zeros(size)
        fixed = list(self.fixed)
        for i, value in prescribed_top.items():
            known[self.top[i]] = value
            fixed.append(self.top[i])
        fixed = np.unique(fixed)
        free = np.setdiff1d(np.arange(size), fixed)
        rhs = -self.matrix[free][:, fixed] @ known[fixed]
        solution = known.copy()
        solution[free] = spla.spsolve(self.matrix[free][:, free].tocsc(), rhs)
        reaction = self.matrix @ solution
        return solution, {i: reaction[self.top[i]] for i in prescribed_top}

    def surface_displacement(self, pressure):
        """u_z of the surface nodes under the surface pressure p(r) (downwards), no indenter: consistent nodal
        loads int N_a p 2 pi r dr on each element's top edge (3 Gauss points; put a jump of p on a vertex)."""
        load = np.zeros(self.matrix.shape[0])
        for er in range(len(self.rv) - 1):
            r0, r1 = self.rv[er], self.rv[er + 1]
            for gx, wx in zip(GAUSS_X, GAUSS_W):
                shape, _ = quadratic(gx)
                rr = 0.5 * (r0 + r1) + 0.5 * (r1 - r0) * gx
                for a in range(3):
                    load[self.top[2 * er + a]] -= wx * 0.5 * (r1 - r0) * shape[a] * pressure(rr) * 2.0 * np.pi * rr
        size = self.matrix.shape[0]
        free = np.setdiff1d(np.arange(size), self.fixed)
        solution = np.zeros(size)
        solution[free] = spla.spsolve(self.matrix[free][:, free].tocsc(), load[free])
        return solution[self.top]

    def indenter_at_radius(self, gap, depth, contact_radius):
        """The force of a frictionless rigid axisymmetric indenter of profile gap(r) (f(r), f(0) = 0) at depth d in
        contact exactly over the surface nodes r <= contact_radius (a vertex of the mesh): a mixed boundary-value
        problem with no active set, whose edge lies where it is put. At the force-free edge of the exact solution,
        dF/da = 0 at fixed d, so a contact radius from another solution, exact to e, changes the force at second order
        in e."""
        inside = [i for i in range(self.mr) if self.r[i] <= contact_radius * (1.0 + 1e-12)]
        _, reactions = self.solve({i: -(depth - gap(self.r[i])) for i in inside})
        return -sum(reactions.values())

    def sphere_at_radius(self, radius, depth, contact_radius):
        """indenter_at_radius for a sphere of the given radius."""
        return self.indenter_at_radius(lambda r: radius - np.sqrt(np.maximum(radius ** 2 - r ** 2, 0.0)), depth,
                                       contact_radius)

    def sphere(self, radius, depth, max_iterations=50):
        """Frictionless rigid sphere at depth d: active set on the surface nodes. Returns (force, contact radius)."""
        gap = lambda r: radius - np.sqrt(np.maximum(radius ** 2 - r ** 2, 0.0))  # noqa: E731
        active = set(i for i in range(self.mr) if self.r[i] <= np.sqrt(radius * depth))
        for _ in range(max_iterations):
            u, reactions = self.solve({i: -(depth - gap(self.r[i])) for i in active})
            uz_top = u[self.top]
            tensile = {i for i, f in reactions.items() if f > 0.0}   # a pull on the surface: reaction > 0 (upwards)
            penetrating = {i for i in range(self.mr) if i not in active
                           and uz_top[i] > -(depth - gap(self.r[i])) + 1e-14 * depth}
            if not tensile and not penetrating:
                break
            active = (active - tensile) | penetrating
        force = -sum(reactions.values())
        return force, max(self.r[i] for i in active)
