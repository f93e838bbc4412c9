"""The shocked state of an MPM symmetric plate impact on a material file: a 1 mm plate (2D strip,
20 µm wide, periodic sides, 10 µm cells) at +Up hits its mirror image at -Up, so the material
behind the shock moves at Up relative to the unshocked plate. When the shock has crossed the window
[0.55, 0.85] mm, its mean density rho and pressure give the state; Us follows from mass
conservation, rho0*Us = rho*(Us - Up), and P_RH = rho0*Us*Up (Rankine-Hugoniot); the window's mean
pressure is the EOS pressure P (the mean stress; the longitudinal stress exceeds it by 2Y/3).
Usage: mpm_hugoniot.py SHOCKFIELD MATERIAL_FILE FOLDER UP_KM_S... [--yield PA]
Prints one line per speed: up_km_s us_km_s pressure_GPa pressure_rh_GPa density_kg_m3."""
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import Run, read_toml  # noqa: E402  (the shared run-folder readers)

CASE = """method = "mpm"
[grid]
dim = 2
cell_size = 10e-6
lo = [0.0, 0.0]
hi = [20e-6, 2.1e-3]
[solver]
end_time = {end_time}
[[material]]
name = "m"
file = "{material}"
yield_stress = {yield_stress}
[[body]]
material = "m"
lo = [0.0, 0.0]
hi = [20e-6, 1.0e-3]
[loading]
type = "symmetric"
speed = {speed}
[diagnostics]
window_bottom = 0.55e-3
window_heights = [0.3e-3]
ejecta = false
[output]
series_interval = {end_time}
"""


def shocked_state(shockfield, material, folder, up_km_s, yield_stress):
    eos = read_toml(material)["eos"]
    rho0 = eos["rho0"]
    up = up_km_s * 1e3
    us_guess = eos["c0"] + eos["s"] * up
    # The front leaves y = 1 mm at Us - Up in the lab (the plate moves up at Up): at end_time it is
    # near y = 0.45 mm, past the window, and well before the plate's free face at 0.
    end_time = 0.55e-3 / (us_guess - up)
    os.makedirs(folder, exist_ok=True)
    case = os.path.join(folder, f"up_{up_km_s:.3f}.toml")
    open(case, "w").write(CASE.format(end_time=end_time, material=os.path.abspath(material), speed=up,
                                      yield_stress=yield_stress))
    run = case[:-5]
    subprocess.run([shockfield, "run", case, "--output", run, "--overwrite", "-q"], check=True,
                   stdout=subprocess.DEVNULL)
    row = Run.open(run).series[-1]
    rho = float(row["bottom_h300um_density_mean_kg_m3"])
    pressure = float(row["bottom_h300um_pressure_mean_Pa"])
    us = rho * up / (rho - rho0)
    return up_km_s, us / 1e3, pressure / 1e9, rho0 * us * up / 1e9, rho


if __name__ == "__main__":
    args = sys.argv[1:]
    yield_stress = 0.0
    if "--yield" in args:
        k = args.index("--yield")
        yield_stress = float(args[k + 1])
        del args[k:k + 2]
    shockfield, material, folder = args[:3]
    for up in map(float, args[3:]):
        print(" ".join(f"{v:.6g}" for v in shocked_state(shockfield, material, folder, up, yield_stress)))
