"""Reads a `hikiln dem` checkpoint.h5 for the CLI identity tests: the per-particle arrays in id
order (so runs that ordered their particles differently compare element by element), the bed
statistics' sums and the step."""
import h5py
import numpy as np

PARTICLE_ARRAYS = ["position", "velocity", "angular_velocity", "force", "torque", "wall_shear"]


def particle_state(path):
    f = h5py.File(path, "r")
    order = np.argsort(f["integers/id"][()])
    out = {k: f["reals/" + k][()].reshape(len(order), -1)[order] for k in PARTICLE_ARRAYS}
    for k in ["slip_sum", "angle_sum", "slip_n"]:
        out[k] = f["scalars/" + k][()]
    out["step"] = f.attrs["step"]
    return out
