#!/usr/bin/env bash
# `shockfield bridge` (docs/bridges.md): hugoniot-to-eos on synthetic MD Hugoniot run folders with
# known c0, s (recovered within 3 of the fit's stated standard errors; a quadratic sweep switches
# the fit to quadratic by the |s2| > 3σ criterion), Γ0 from two MD runs against LAMMPS, elastic from stored constants (the LAMMPS
# fixture) and from a short MD run of Cu_u3.eam, both written into one material file that an MPM
# and a PD case then read; bad input refused naming the file and key.
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
"$SF" bridge --help | grep -q "hugoniot-to-eos" || fail "bridge --help lacks hugoniot-to-eos"
"$SF" bridge --help | grep -q "elastic" || fail "bridge --help lacks elastic"

# sweep DIR C0 S S2 NOISE N [METHOD]: N MD-like run folders up_*/ with Us = C0 + S Up + S2 Up² + noise
# (km/s; a fixed pseudo-random sequence of standard deviation NOISE) and ρ0 = 8.93 g/cm³.
sweep() {
  python3 - "$@" <<'EOF'
import os, random, sys
d, c0, s, s2, noise, n = sys.argv[1], *map(float, sys.argv[2:6]), int(sys.argv[6])
method = sys.argv[7] if len(sys.argv) > 7 else "md"
rng = random.Random(2026)
for k in range(n):
    up = 0.5 + 1.5 * k / (n - 1)
    us = c0 + s * up + s2 * up * up + rng.gauss(0.0, noise)
    f = os.path.join(d, "up_%.2f" % (up / 0.75))
    os.makedirs(f, exist_ok=True)
    open(os.path.join(f, "config.resolved.toml"), "w").write('method = "%s"\n[derived]\natoms = 100\n' % method)
    open(os.path.join(f, "hugoniot_shock.toml"), "w").write(
        "us_km_s = %r\nup_km_s = %r\npiston_speed_km_s = %r\ndensity0_g_cc = %r\ncomplete = true\nnote = \"\"\n"
        % (us, up, up / 0.75, 8.93 + 0.001 * (k % 3 - 1)))
EOF
}
source "$(dirname "$0")/bridge_lib.bash"

sweep "$WORK/lin" 3.90 1.55 0.0 0.02 8
"$SF" bridge hugoniot-to-eos "$WORK/lin" -o "$WORK/cu.toml" --name cu_md > "$WORK/eos.txt"
f="$WORK/cu.toml"
c0=$(value "$f" eos.c0); s=$(value "$f" eos.s)
c0e=$(value "$f" provenance.hugoniot_to_eos.fit.c0_stderr_m_s); se=$(value "$f" provenance.hugoniot_to_eos.fit.s_stderr)
echo "linear: c0 = $c0 +- $c0e m/s (3900), s = $s +- $se (1.55)"
within "$c0" 3900 "$c0e" 3 || fail "c0 = $c0 +- $c0e not within 3 sigma of 3900"
within "$s" 1.55 "$se" 3 || fail "s = $s +- $se not within 3 sigma of 1.55"
python3 -c "import sys; sys.exit(0 if 5 < float(sys.argv[1]) < 40 else 1)" "$c0e" || fail "implausible c0 error $c0e"
[ "$(value "$f" provenance.hugoniot_to_eos.fit.model)" = linear ] || fail "a linear sweep was fitted quadratically"
within "$(value "$f" eos.rho0)" 8930 1 1 || fail "rho0 is not the MD density"
[ "$(value "$f" eos.gamma0)" = 2.02 ] || fail "gamma0 is not the library copper's"
grep -q "not measured by these MD runs" "$f" || fail "the file does not say where gamma0 came from"
sha=$(sha256sum "$WORK/lin/up_0.67/config.resolved.toml" | cut -d' ' -f1)
grep -qF "$sha" "$f" || fail "provenance lacks the SHA-256 of an input's resolved configuration"
[ "$(value "$f" provenance.hugoniot_to_eos.inputs | grep -o folder | wc -l)" -eq 8 ] || fail "provenance lacks inputs"

sweep "$WORK/quad" 3.90 1.50 0.08 0.01 8
"$SF" bridge hugoniot-to-eos "$WORK/quad" -o "$WORK/quad.toml" > /dev/null
[ "$(value "$WORK/quad.toml" provenance.hugoniot_to_eos.fit.model)" = quadratic ] || fail "auto kept a linear fit"
s2=$(value "$WORK/quad.toml" eos.s2); s2e=$(value "$WORK/quad.toml" provenance.hugoniot_to_eos.fit.s2_stderr_s_m)
echo "quadratic: s2 = $s2 +- $s2e s/m (8e-5)"
within "$s2" 8e-5 "$s2e" 3 || fail "s2 = $s2 +- $s2e not within 3 sigma of 8e-5"
"$SF" bridge hugoniot-to-eos "$WORK/quad" -o "$WORK/quad_lin.toml" --quadratic no > /dev/null
[ "$(value "$WORK/quad_lin.toml" provenance.hugoniot_to_eos.fit.model)" = linear ] || fail "--quadratic no"

# Γ0 from MD (--gamma0-md): the thermal pressure of Cu_u3.eam at constant volume, against LAMMPS
# doing the same (tests/fixtures/lammps_gruneisen, Γ = 1.819 ± 0.041): both are Langevin averages,
# so they agree within 3 of their combined standard errors.
sweep "$WORK/gmd" 3.90 1.55 0.0 0.02 4
cp "$ROOT/examples/bridge_cu_atoms_to_plate/md_piston.toml" "$WORK/gmd/up_0.67/config.resolved.toml"
"$SF" bridge hugoniot-to-eos "$WORK/gmd" -o "$WORK/gmd.toml" --gamma0-md --gamma0-md-steps 2000 > /dev/null
g=$(value "$WORK/gmd.toml" provenance.hugoniot_to_eos.fit.gamma_md)
ge=$(value "$WORK/gmd.toml" provenance.hugoniot_to_eos.fit.gamma_md_stderr)
lg=$(value "$ROOT/tests/fixtures/lammps_gruneisen/results.toml" gamma)
lge=$(value "$ROOT/tests/fixtures/lammps_gruneisen/results.toml" gamma_stderr)
echo "gamma from MD: $g +- $ge (LAMMPS $lg +- $lge)"
within "$g" "$lg" "$(python3 -c "import math, sys; print(math.hypot(*map(float, sys.argv[1:])))" "$ge" "$lge")" 3 \
  || fail "MD Gruneisen $g +- $ge differs from LAMMPS $lg +- $lge"
grep -q "from MD: Gamma = V dP/dE" "$WORK/gmd.toml" || fail "the file does not say gamma0 is from MD"

# elastic from the LAMMPS fixture's constants, written into the same file.
"$SF" bridge elastic --constants "$ROOT/tests/fixtures/lammps_elastic/results.toml" --mass 63.546 -o "$f" --update \
  --average voigt > /dev/null
[ "$(value "$f" elasticity.c11)" = 167264636877.242 ] || fail "c11 is not the fixture's: $(value "$f" elasticity.c11)"
within "$(value "$f" elasticity.shear)" "$(python3 -c 'print((167.264636877242-124.153786879514+3*76.4477802979291)/5*1e9)')" 1 1 \
  || fail "Voigt shear"
within "$(value "$f" elasticity.density)" "$(python3 -c 'print(4*63.546*1.66053904/3.61499997576462**3*1e3)')" 1e-6 1 \
  || fail "density of the relaxed crystal"
[ "$(value "$f" eos.c0)" = "$c0" ] || fail "--update lost [eos]"
value "$f" provenance.hugoniot_to_eos.command > /dev/null || fail "--update lost the EOS provenance"
# ... and from a short MD run of the potential (0 K, 3x3x3 cells): the same constants to 1e-6
# (the fixture is 4x4x4; the fcc crystal has no internal relaxation, so the size does not matter).
"$SF" bridge elastic --potential Cu_u3.eam --a0 3.6 --repeat 3 -o "$WORK/md.toml" > /dev/null
within "$(value "$WORK/md.toml" elasticity.c44)" 76447780297.9291 76447.78 1 || fail "MD C44 differs from LAMMPS"
grep -qF "$(sha256sum /usr/share/lammps/potentials/Cu_u3.eam | cut -d' ' -f1)" "$WORK/md.toml" || fail "no potential hash"

# The bridged file in an MPM and a PD case (strength from the case: MD gives none here).
sed -e 's|library = "aluminium_seed000"|file = "cu.toml"\nyield_stress = 120e6|' -e 's|speed = 1000.0|speed = 500.0|' \
  "$ROOT/tests/cli/cases/mpm_tiny.toml" > "$WORK/mpm.toml"
"$SF" run "$WORK/mpm.toml" --output "$WORK/mpm" -q > /dev/null
grep -qF "provenance.hugoniot_to_eos.fit.c0_stderr_m_s = $c0e" "$WORK/mpm/log.txt" || fail "MPM log lacks the fit"
printf '%s\n' "$(sed -e 's|model = "j2"|model = "crystal"\nfile = "cu.toml"|' -e '/^density\|^young\|^poisson\|^yield_stress/d' \
  "$ROOT/tests/cli/cases/pd_tiny.toml")" > "$WORK/pd.toml"
"$SF" run "$WORK/pd.toml" --output "$WORK/pd" -q > /dev/null
grep -q "^c11 = 167264636877.242" "$WORK/pd/config.resolved.toml" || fail "PD did not take the bridged c11"
echo "ok: bridged EOS and elasticity fit, written, read by MPM and PD"

# Bad input: each refused with exit 2, naming the file and key (bad: bridge_lib.bash).
sweep "$WORK/two" 3.9 1.5 0 0.01 2
bad "2 Hugoniot points" "hugoniot_shock.toml" "at least three" -- hugoniot-to-eos "$WORK/two" -o "$WORK/x.toml"
sweep "$WORK/mpm_runs" 3.9 1.5 0 0.01 3 mpm
bad "config.resolved.toml" "key 'method'" '"mpm"' -- hugoniot-to-eos "$WORK/mpm_runs" -o "$WORK/x.toml"
sweep "$WORK/neg" 6.0 -0.5 0 0.001 4
bad "us_km_s against up_km_s" "s = -0." "< 0" -- hugoniot-to-eos "$WORK/neg" -o "$WORK/x.toml"
sweep "$WORK/c0" -1.0 4.0 0 0.001 4
bad "c0 = -" "outside the range of the measured shock speeds" -- hugoniot-to-eos "$WORK/c0" -o "$WORK/x.toml"
sweep "$WORK/open" 3.9 1.5 0 0.01 3
sed -i 's/complete = true/complete = false/' "$WORK/open/up_0.67/hugoniot_shock.toml"
bad "up_0.67/hugoniot_shock.toml" "key 'complete'" -- hugoniot-to-eos "$WORK/open" -o "$WORK/x.toml"
bad "neither a run folder" -- hugoniot-to-eos "$WORK" -o "$WORK/x.toml"
bad "either --potential" -- elastic -o "$WORK/x.toml"
printf 'a0_A = 3.6\nc11_GPa = 100\nc12_GPa = 120\nc44_GPa = 50\n' > "$WORK/unstable.toml"
bad "unstable.toml" "not a stable cubic crystal" -- elastic --constants "$WORK/unstable.toml" --mass 63.5 -o "$WORK/x.toml"
printf 'a0_A = 3.6\nc11_GPa = 100\n' > "$WORK/short.toml"
bad "short.toml" "key 'c12_GPa'" -- elastic --constants "$WORK/short.toml" --mass 63.5 -o "$WORK/x.toml"
[ ! -e "$WORK/x.toml" ] || fail "a refused bridge wrote its output"
echo "bridge: ok"
