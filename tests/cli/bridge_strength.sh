#!/usr/bin/env bash
# `shockfield bridge spall` and `bridge yield` (docs/bridges.md) on synthetic MD run folders with a
# known answer: a tension curve with a known peak before an abrupt drop (cusp and rounded, with
# and without noise) and a [111] uniaxial-strain compression with a known elastic-plastic break;
# recovered within the bridge's stated standard error (3σ with noise; 2σ without, where the
# error is the sampling term Δ/√12 and the true peak lies within Δ/2 = √3σ of the estimate). Then
# one short real MD tension run of Cu_u3.eam; bad input refused naming the folder or file.
source "$(dirname "$0")/lib.bash"
source "$(dirname "$0")/bridge_lib.bash"
set -e
export OMP_NUM_THREADS=1
for b in spall yield; do "$SF" bridge --help | grep -q "  $b" || fail "bridge --help lacks $b"; done

# synth DIR KIND NOISE [ROWS]: a run folder (config.resolved.toml + thermo.csv, rows every 0.04 ps).
# KIND tension_cusp: tensile mean stress A(1 − exp(−t/τ)) until t_n, then falls to 30% within
#   0.3 ps; uniaxial strain along z at 0.01/ps. Prints the true peak (Pa) and the true
#   volumetric rate at it (1/s).
# KIND tension_round: A − k(t − t_p)² with the drop at t_p + 0.3 ps. KIND compression_111: [111]
#   along z, σ_L = P0 + E ε, σ_T = P0 + r E ε until the break at t_b, then σ_L − σ_T halves;
#   prints HEL, Y = (1 − r) HEL, g0 = m Y (m = 2/(3√6)).
synth() {
  python3 - "$@" <<'EOF'
import math, os, random, sys
d, kind, noise = sys.argv[1], sys.argv[2], float(sys.argv[3])
rows = int(sys.argv[4]) if len(sys.argv) > 4 else 700
os.makedirs(d, exist_ok=True)
rng = random.Random(19)
rate = 0.01 if kind.startswith("tension") else -0.01  # 1/ps
orient = 'orient_x = [1, -1, 0]\norient_y = [1, 1, -2]\norient_z = [1, 1, 1]\n' if kind == "compression_111" else ""
open(os.path.join(d, "config.resolved.toml"), "w").write(
    'method = "md"\n[system.lattice]\nstyle = "fcc"\na0 = 3.615\n%s\n'
    '[[stage]]\nname = "equilibrate"\nensemble = "nvt"\nsteps = 200\n\n'
    '[[stage]]\nname = "load"\nensemble = "nve"\nsteps = %d\ndeform_rate = [0.0, 0.0, %r]\n'
    % (orient, 20 * (rows - 1), rate))
A, tau, tn, tp, k = 20e9, 15.0, 20.31, 18.0, 0.05e9
P0, E, r, tb = 1.8e9, 400e9, 0.5, 15.37
out = open(os.path.join(d, "thermo.csv"), "w")
out.write("step,time_ps,temperature_K,press_bar,pxx_bar,pyy_bar,pzz_bar,pxy_bar,pxz_bar,pyz_bar,volume_A3,lx_A,ly_A,lz_A\n")
for step in range(0, 200 + 20 * rows, 20):
    t = max(0.0, (step - 200) * 0.002)  # ps into the load stage
    strain = rate * t
    if kind == "tension_cusp":
        peak = A * (1 - math.exp(-tn / tau))
        y = A * (1 - math.exp(-min(t, tn) / tau))
        if t > tn: y = peak * max(0.3, 1 - 0.7 * (t - tn) / 0.3)
        pl = pt = -y
    elif kind == "tension_round":
        y = A - k * (t - tp) ** 2
        if t > tp + 0.3: y = 0.3 * A
        pl = pt = -y
    else:
        eb = abs(rate) * tb
        e = abs(strain)
        dl, dt = E * e, r * E * e
        if t > tb: dt = dl - 0.5 * (1 - r) * E * eb
        pl, pt = P0 + dl, P0 + dt
    pl += rng.gauss(0, noise); pt += rng.gauss(0, noise)
    press = (pl + 2 * pt) / 3
    L = 20.0 * (1 + strain)
    out.write("%d,%r,300,%r,%r,%r,%r,0,0,0,%r,20,20,%r\n" % (step, step * 0.002, press / 1e5, pt / 1e5, pt / 1e5,
              pl / 1e5, 400 * L, L))
if kind == "tension_cusp": print(A * (1 - math.exp(-tn / tau)), 1e10 / (1 + 0.01 * tn))
elif kind == "tension_round": print(A, 1e10 / (1 + 0.01 * tp))
else:
    hel = E * abs(rate) * tb
    print(hel, (1 - r) * hel, 2 / (3 * math.sqrt(6)) * (1 - r) * hel)
EOF
}
# check NAME VALUE TRUE STDERR N: |VALUE − TRUE| ≤ N·STDERR
check() {
  echo "$1: $2 +- $4 (true $3)"
  within "$2" "$3" "$4" "$5" || fail "$1 = $2 +- $4 is not within $5 sigma of $3"
}

# spall: a cusp (rising until nucleation) and a rounded maximum; noise-free and with 0.03 GPa noise.
for kind in tension_cusp tension_round; do
  for noise in 0 3e7; do
    read -r peak rate < <(synth "$WORK/$kind$noise" "$kind" "$noise")
    "$SF" bridge spall "$WORK/$kind$noise" -o "$WORK/s.toml" --name cu_md > /dev/null
    f="$WORK/s.toml"
    n=$([ "$noise" = 0 ] && echo 2 || echo 3)
    check "$kind noise $noise: spall strength" "$(value "$f" spall.strength)" "$peak" \
      "$(value "$f" provenance.spall.fit.strength_stderr_Pa)" "$n"
    within "$(value "$f" spall.strain_rate)" "$rate" "$rate" 0.005 || fail "strain rate $(value "$f" spall.strain_rate), true $rate"
  done
done
python3 -c "import sys; sys.exit(0 if 1e6 < float(sys.argv[1]) < 1e8 else 1)" \
  "$(value "$f" provenance.spall.fit.strength_stderr_Pa)" || fail "implausible stderr with 0.03 GPa noise"
grep -qF "$(sha256sum "$WORK/tension_round3e7/thermo.csv" | cut -d' ' -f1)" "$f" || fail "no thermo.csv hash in provenance"
grep -q "upper bound" "$f" || fail "the spall note lacks the MD-rate caveat"

# yield: [111], Schmid factor 2/(3√6) = 0.2722; ν from the elastic rise (r = σT/σL rise = 0.5 → ν = 1/3).
read -r hel y g0 < <(synth "$WORK/c111" compression_111 2e7)
"$SF" bridge yield "$WORK/c111" -o "$WORK/y.toml" > /dev/null
f="$WORK/y.toml"
check "HEL" "$(value "$f" provenance.yield.fit.hel_Pa)" "$hel" "$(value "$f" provenance.yield.fit.hel_stderr_Pa)" 3
check "Y" "$(value "$f" strength.yield_stress)" "$y" "$(value "$f" provenance.yield.fit.yield_stress_stderr_Pa)" 3
check "g0" "$(value "$f" strength.g0)" "$g0" "$(value "$f" provenance.yield.fit.g0_stderr_Pa)" 3
within "$(value "$f" provenance.yield.fit.schmid_factor)" 0.272165527 1e-8 1 || fail "Schmid factor of [111]"
within "$(value "$f" provenance.yield.fit.poisson)" 0.3333333 0.01 1 || fail "measured poisson"
within "$(value "$f" strength.strain_rate)" 1.18e10 1e8 1 || fail "strain rate"
grep -q "MD strain rates" "$f" || fail "the strength note lacks the MD-rate caveat"
# The Schmid factor of other loading directions: [001] (no orient) and [-1-10] (orient_x = [1,-1,0],
# orient_y = [0,0,1]): 1/√6 = 0.408248 for both (the same synthetic stresses).
for d in 001 110; do
  cp -r "$WORK/c111" "$WORK/c$d"
  if [ $d = 001 ]; then sed -i '/^orient_/d' "$WORK/c$d/config.resolved.toml"
  else sed -i -e 's/^orient_y = .*/orient_y = [0, 0, 1]/' -e 's/^orient_z = .*/orient_z = [-1, -1, 0]/' "$WORK/c$d/config.resolved.toml"; fi
  "$SF" bridge yield "$WORK/c$d" -o "$WORK/y$d.toml" > /dev/null
  within "$(value "$WORK/y$d.toml" provenance.yield.fit.schmid_factor)" 0.40824829 1e-7 1 || fail "Schmid factor of [$d]"
  within "$(value "$WORK/y$d.toml" strength.g0)" "$(python3 -c "print($g0 * 0.40824829 / 0.27216553)")" \
    "$(value "$WORK/y$d.toml" provenance.yield.fit.g0_stderr_Pa)" 3 || fail "g0 along [$d]"
done
# --poisson 0.3: Y = HEL (1 − 2ν)/(1 − ν) = HEL·4/7, written into an existing file (--update keeps [spall]).
"$SF" bridge spall "$WORK/tension_cusp0" -o "$WORK/both.toml" > /dev/null
"$SF" bridge yield "$WORK/c111" -o "$WORK/both.toml" --update --poisson 0.3 > /dev/null
within "$(value "$WORK/both.toml" strength.yield_stress)" "$(python3 -c "print($(value "$f" provenance.yield.fit.hel_Pa) * 4 / 7)")" 1 1 \
  || fail "Y with --poisson 0.3"
value "$WORK/both.toml" spall.strength > /dev/null || fail "--update lost [spall]"
echo "ok: spall and yield recovered from synthetic runs"

# A real MD tension run: 256 atoms of Cu_u3.eam in uniaxial strain at 2e10/s past void nucleation;
# the spall strength of the perfect crystal is 10-20 GPa (14.8 GPa at 864 atoms and 1e10/s).
cat > "$WORK/md.toml" <<EOF
method = "md"
[system.lattice]
style = "fcc"
a0 = 3.615
repeat = [4, 4, 4]
boundary = "ppp"
elements = ["Cu"]
[potential]
style = "eam"
file = "Cu_u3.eam"
[md]
timestep = 0.002
[velocity]
temperature = 300.0
[output]
thermo_every = 10
[[stage]]
name = "tension"
ensemble = "nve"
steps = 7000
deform_rate = [0.0, 0.0, 0.02]
EOF
"$SF" run "$WORK/md.toml" -o "$WORK/md" -q > /dev/null
"$SF" bridge spall "$WORK/md" -o "$WORK/md_spall.toml"
python3 -c "import sys; sys.exit(0 if 10e9 < float(sys.argv[1]) < 20e9 else 1)" "$(value "$WORK/md_spall.toml" spall.strength)" \
  || fail "MD spall strength $(value "$WORK/md_spall.toml" spall.strength) outside 10-20 GPa"

# Bad input: exit 2, naming the folder or file and what was expected.
bad "not a run folder" "$WORK/nowhere" -- spall "$WORK/nowhere" -o "$WORK/x.toml"
mkdir -p "$WORK/mpm_run" && printf 'method = "mpm"\n' > "$WORK/mpm_run/config.resolved.toml"
bad "mpm_run/config.resolved.toml" 'method = "mpm"' "MD tension run" -- spall "$WORK/mpm_run" -o "$WORK/x.toml"
mkdir -p "$WORK/flyer" && printf 'method = "md"\n[[stage]]\nname = "impact"\nsteps = 3000\n' > "$WORK/flyer/config.resolved.toml"
bad "flyer/config.resolved.toml" "no [[stage]] with deform_rate" "flyer-plate" -- spall "$WORK/flyer" -o "$WORK/x.toml"
bad "c111/config.resolved.toml" "deform_rate [0, 0, -0.01]" "tension" -- spall "$WORK/c111" -o "$WORK/x.toml"
bad "tension_cusp0/config.resolved.toml" "compression" -- yield "$WORK/tension_cusp0" -o "$WORK/x.toml"
# Out-of-range stage values (found by the fuzz target bridge_spall, seed 2): refused naming the key.
synth "$WORK/rate" tension_cusp 0 > /dev/null
sed -i 's/deform_rate = \[0.0, 0.0, 0.01\]/deform_rate = [1e300, 0.0, 0.01]/' "$WORK/rate/config.resolved.toml"
bad "rate/config.resolved.toml" "key 'stage[1].deform_rate'" "[-10, 10]" -- spall "$WORK/rate" -o "$WORK/x.toml"
synth "$WORK/steps" tension_cusp 0 > /dev/null
sed -i 's/^steps = 13980/steps = -9223372036854775808/' "$WORK/steps/config.resolved.toml"
bad "steps/config.resolved.toml" "key 'stage[1].steps'" -- spall "$WORK/steps" -o "$WORK/x.toml"
sed -i 's/orient_z = \[1, 1, 1\]/orient_z = [0, 0, 0]/' "$WORK/c111/config.resolved.toml"
bad "c111/config.resolved.toml" "key 'system.lattice.orient_z'" -- yield "$WORK/c111" -o "$WORK/x.toml"
synth "$WORK/short" tension_cusp 0 6 > /dev/null
bad "short/thermo.csv" "thermo rows" "expected at least 10" -- spall "$WORK/short" -o "$WORK/x.toml"
synth "$WORK/nodrop" tension_cusp 0 480 > /dev/null  # ends at 19.2 ps, before nucleation
bad "nodrop/thermo.csv" "no void nucleation found" "(the last row)" "run the stage longer" -- spall "$WORK/nodrop" -o "$WORK/x.toml"
synth "$WORK/nobreak" compression_111 0 300 > /dev/null  # ends at 12 ps, before the break
bad "nobreak/thermo.csv" "no elastic-plastic break found" -- yield "$WORK/nobreak" -o "$WORK/x.toml"
# A smooth maximum (the elastic softening of [100] fcc): sin² rise and fall, no abrupt drop.
synth "$WORK/smooth" tension_cusp 0 > /dev/null
python3 - "$WORK/smooth/thermo.csv" <<'EOF'
import math, sys
rows = open(sys.argv[1]).read().splitlines()
out = [rows[0]]
for line in rows[1:]:
    c = line.split(","); t = max(0.0, (int(c[0]) - 200) * 0.002)
    y = 15e9 * math.sin(math.pi * t / 28.0); c[3] = c[4] = c[5] = c[6] = repr(-y / 1e5); out.append(",".join(c))
open(sys.argv[1], "w").write("\n".join(out) + "\n")
EOF
bad "smooth/thermo.csv" "a smooth maximum" "not a break" -- spall "$WORK/smooth" -o "$WORK/x.toml"
sed -i 's/press_bar/pressure/' "$WORK/smooth/thermo.csv"
bad "smooth/thermo.csv" "no column 'press_bar'" -- spall "$WORK/smooth" -o "$WORK/x.toml"
[ ! -e "$WORK/x.toml" ] || fail "a refused bridge wrote its output"
echo "bridge_strength: ok"
