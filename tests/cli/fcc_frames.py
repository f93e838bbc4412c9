"""Shared by the CLI tests: fcc lattice sites and a LAMMPS text dump writer (numpy)."""
import numpy as np

BASIS = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])


def fcc_sites(a, n):
    """The sites of n×n×n conventional cells of lattice constant a, from the origin."""
    cells = np.stack(np.meshgrid(*[np.arange(n)] * 3, indexing="ij"), -1).reshape(-1, 3)
    return (cells[:, None, :] + BASIS[None]).reshape(-1, 3) * a


def write_dump(path, x, length, timestep):
    """One frame, periodic cubic box [0, length)³, columns id type x y z."""
    with open(path, "w") as f:
        f.write(f"ITEM: TIMESTEP\n{timestep}\nITEM: NUMBER OF ATOMS\n{len(x)}\nITEM: BOX BOUNDS pp pp pp\n")
        f.write(f"0 {length}\n0 {length}\n0 {length}\nITEM: ATOMS id type x y z\n")
        for i, p in enumerate(x, 1):
            f.write(f"{i} 1 {p[0]:.8f} {p[1]:.8f} {p[2]:.8f}\n")
