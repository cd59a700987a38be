"""Analytic test surfaces for the curvature experiment: meshes and exact curvature.

The same surfaces and meshings as tests/support/analytic_surfaces.cpp, written independently in
numpy so that the experiment checks the C++ estimators against formulas it does not
share with them. Sign convention as common/curvature/curvature.hpp: k > 0 where the surface bends
away from its normal. Meshes: regular (a grid with one diagonal), irregular (vertices
jittered by up to 0.15 of a cell per grid direction, each quad's diagonal random) or
strong (jittered by up to 0.45 of a cell, a spread of 0.9: about 1% of the triangles fold
over; issue 19). A surface function's `irregular` argument is the jitter (0: regular).
"""
import numpy as np

JITTER = {"regular": 0.0, "irregular": 0.15, "strong": 0.45}


def write_obj(path, positions, triangles):
    """The mesh as an OBJ file, positions to 9 significant digits (what both studies read back)."""
    with open(path, "w") as f:
        f.writelines("v %.9g %.9g %.9g\n" % tuple(p) for p in positions)
        f.writelines("f %d %d %d\n" % tuple(t + 1) for t in triangles)


def _quads_to_triangles(a, b, c, d, irregular, rng):
    """Quads (a, b, c, d) counter-clockwise from outside -> triangles."""
    flip = rng.random(len(a)) < 0.5 if irregular > 0 else np.zeros(len(a), bool)
    t1 = np.where(flip[:, None], np.stack([a, b, d], 1), np.stack([a, b, c], 1))
    t2 = np.where(flip[:, None], np.stack([b, c, d], 1), np.stack([a, c, d], 1))
    return np.concatenate([t1, t2])


def grid_mesh(nu, nv, wrap_u, wrap_v, surface_map, irregular, rng):
    """An nu x nv cell grid over [0,1]^2 mapped by surface_map(u, v) -> (n, 3)."""
    cu, cv = (nu if wrap_u else nu + 1), (nv if wrap_v else nv + 1)
    j, i = np.meshgrid(np.arange(cv), np.arange(cu), indexing="ij")
    u, v = (i / nu).ravel(), (j / nv).ravel()
    if irregular > 0:
        du = rng.uniform(-irregular, irregular, u.size) / nu
        dv = rng.uniform(-irregular, irregular, v.size) / nv
        ii, jj = i.ravel(), j.ravel()
        u = u + np.where(wrap_u | ((ii > 0) & (ii < nu)), du, 0)
        v = v + np.where(wrap_v | ((jj > 0) & (jj < nv)), dv, 0)
    positions = surface_map(u, v)
    qj, qi = np.meshgrid(np.arange(nv), np.arange(nu), indexing="ij")
    qi, qj = qi.ravel(), qj.ravel()

    def index(a, b):
        return (b % cv) * cu + (a % cu)

    tris = _quads_to_triangles(index(qi, qj), index(qi + 1, qj), index(qi + 1, qj + 1), index(qi, qj + 1),
                               irregular, rng)
    return positions, tris


_CUBE_FACES = [((1, 0, 0), (0, 1, 0), (0, 0, 1)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
               ((0, 1, 0), (0, 0, 1), (1, 0, 0)), ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
               ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (0, 1, 0), (1, 0, 0))]


def unit_cube_sphere(n, irregular, rng):
    """The cube [-1,1]^3 as n x n cells per face, spread onto the unit sphere."""
    lattice, points, tris = {}, [], []

    def vertex(f, s, t):
        q = np.array(f[0]) + (2.0 * s / n - 1) * np.array(f[1]) + (2.0 * t / n - 1) * np.array(f[2])
        key = tuple(np.rint((q + 1) * 0.5 * n).astype(int))
        if key not in lattice:
            lattice[key] = len(points)
            points.append(q)
        return lattice[key]

    for f in _CUBE_FACES:
        for t in range(n):
            for s in range(n):
                tris.append((vertex(f, s, t), vertex(f, s + 1, t), vertex(f, s + 1, t + 1), vertex(f, s, t + 1)))
    q = np.array(points)
    if irregular > 0:
        q = q + (2.0 * irregular / n) * rng.uniform(-1, 1, q.shape)
        q = q / np.abs(q).max(axis=1, keepdims=True)
    s = q * q
    sphere = q * np.sqrt(np.stack([1 - s[:, 1] / 2 - s[:, 2] / 2 + s[:, 1] * s[:, 2] / 3,
                                   1 - s[:, 2] / 2 - s[:, 0] / 2 + s[:, 2] * s[:, 0] / 3,
                                   1 - s[:, 0] / 2 - s[:, 1] / 2 + s[:, 0] * s[:, 1] / 3], 1))
    quads = np.array(tris)
    return sphere, _quads_to_triangles(quads[:, 0], quads[:, 1], quads[:, 2], quads[:, 3], irregular, rng)


def implicit_truth(gradient, hessian):
    """Principal curvatures and directions of F = 0 from grad F (n, 3) and Hess F (n, 3, 3)."""
    g = np.linalg.norm(gradient, axis=1, keepdims=True)
    normal = gradient / g
    projector = np.eye(3)[None] - normal[:, :, None] * normal[:, None, :]
    shape = projector @ hessian @ projector / g[:, :, None]  # II(t, t) = tᵀ H t / |grad F|
    values, vectors = np.linalg.eigh(shape)
    # One eigenvalue belongs to the normal (0 after projection): drop the eigenvector most along it.
    along = np.abs(np.einsum("nij,ni->nj", vectors, normal))
    keep = np.argsort(along, axis=1)[:, :2]
    k = np.take_along_axis(values, keep, 1)
    d = np.take_along_axis(vectors, keep[:, None, :], 2)
    order = np.argsort(k, axis=1)
    k = np.take_along_axis(k, order, 1)
    d_min = np.take_along_axis(d, order[:, None, :1], 2)[:, :, 0]
    return normal, k[:, 0], k[:, 1], d_min


def ellipsoid(axes, edge, irregular, rng):
    n = max(3, int(np.ceil(0.5 * np.pi * max(axes) / edge)))
    unit, tris = unit_cube_sphere(n, irregular, rng)
    positions = unit * np.array(axes)

    def truth(p):
        inv = 1.0 / np.array(axes) ** 2
        return implicit_truth(2 * p * inv, np.broadcast_to(np.diag(2 * inv), (len(p), 3, 3)))

    return positions, tris, truth


def sphere(radius, edge, irregular, rng):
    return ellipsoid((radius, radius, radius), edge, irregular, rng)


def cylinder(radius, height, edge, irregular, rng):
    def surface_map(u, v):
        phi = 2 * np.pi * u
        return np.stack([radius * np.cos(phi), radius * np.sin(phi), height * v], 1)

    positions, tris = grid_mesh(max(3, int(np.ceil(2 * np.pi * radius / edge))), max(3, int(np.ceil(height / edge))),
                                True, False, surface_map, irregular, rng)

    def truth(p):
        normal = p * np.array([1, 1, 0])
        normal /= np.linalg.norm(normal, axis=1, keepdims=True)
        zeros = np.zeros(len(p))
        return normal, zeros, zeros + 1 / radius, np.tile([0.0, 0.0, 1.0], (len(p), 1))

    return positions, tris, truth


def torus(big_r, small_r, edge, irregular, rng):
    def surface_map(u, v):
        phi, theta = 2 * np.pi * u, 2 * np.pi * v
        w = big_r + small_r * np.cos(theta)
        return np.stack([w * np.cos(phi), w * np.sin(phi), small_r * np.sin(theta)], 1)

    positions, tris = grid_mesh(max(3, int(np.ceil(2 * np.pi * big_r / edge))),
                                max(3, int(np.ceil(2 * np.pi * small_r / edge))), True, True, surface_map, irregular,
                                rng)

    def truth(p):
        phi = np.arctan2(p[:, 1], p[:, 0])
        theta = np.arctan2(p[:, 2], np.hypot(p[:, 0], p[:, 1]) - big_r)
        normal = np.stack([np.cos(theta) * np.cos(phi), np.cos(theta) * np.sin(phi), np.sin(theta)], 1)
        parallel = np.stack([-np.sin(phi), np.cos(phi), np.zeros(len(p))], 1)
        return normal, np.cos(theta) / (big_r + small_r * np.cos(theta)), np.full(len(p), 1 / small_r), parallel

    return positions, tris, truth


def saddle(s, edge, irregular, rng):
    """z = s (x^2 - y^2) over [-1, 1]^2, normal towards +z."""
    def surface_map(u, v):
        x, y = 2 * u - 1, 2 * v - 1
        return np.stack([x, y, s * (x * x - y * y)], 1)

    n = max(3, int(np.ceil(2 / edge)))
    positions, tris = grid_mesh(n, n, False, False, surface_map, irregular, rng)

    def truth(p):
        gradient = np.stack([-2 * s * p[:, 0], 2 * s * p[:, 1], np.ones(len(p))], 1)
        return implicit_truth(gradient, np.broadcast_to(np.diag([-2 * s, 2 * s, 0.0]), (len(p), 3, 3)))

    return positions, tris, truth


SURFACES = {
    "torus": lambda edge, irr, rng: torus(1.0, 0.5, edge, irr, rng),
    "ellipsoid": lambda edge, irr, rng: ellipsoid((1.0, 0.7, 0.5), edge, irr, rng),
    "sphere": lambda edge, irr, rng: sphere(1.0, edge, irr, rng),
    "cylinder": lambda edge, irr, rng: cylinder(0.5, 1.0, edge, irr, rng),
    "saddle": lambda edge, irr, rng: saddle(0.5, edge, irr, rng),
}
