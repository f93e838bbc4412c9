#!/usr/bin/env bash
# The collapsibility study of examples/mpm_cavity_collapsibility (Xu et al. 2015, §4.2.1, Fig 53) at
# twice its cell size (1 µm cells, 0.5 µm spacing, under 1 s of CPU a run): Φ = (A0 − A)/A0 at
# the end (20 ns) must fall with the cavity radius (4.4 → 8 µm at σ_Y0 = 120 MPa) and with the
# initial yield stress (40 → 360 MPa at r = 6.2 µm), by margins the full-resolution study
# exceeds (README: Φ_end 0.98 → 0.50 and 0.88 → 0.51; here 0.92 → 0.50 and 0.87 → 0.50).
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
example="$ROOT/examples/mpm_cavity_collapsibility/case.toml"
# phi_end RADIUS_UM YIELD_MPA: Φ in the last row of series.csv of the coarsened case.
phi_end() {
  local name="r$1_Y$2"
  sed -e "s/^cavity_radius = .*/cavity_radius = $1e-6/" -e "s/^yield_stress = .*/yield_stress = $2e6/" \
      -e "s/^cell_size = .*/cell_size = 1e-6/" -e "s/^spacing = .*/spacing = 0.5e-6/" \
      -e "s/^series_interval = .*/series_interval = 1e-9/" "$example" > "$WORK/$name.toml"
  "$SF" run "$WORK/$name.toml" --output "$WORK/$name" -q > /dev/null
  awk -F, 'NR == 1 { for (k = 1; k <= NF; ++k) if ($k == "collapsibility") c = k }
           END { if (!c) exit 1; print $c }' "$WORK/$name/series.csv"
}
# above A B MARGIN: A exceeds B by more than MARGIN.
above() { awk -v a="$1" -v b="$2" -v m="$3" 'BEGIN { exit !(a - b > m) }'; }

small=$(phi_end 4.4 120) large=$(phi_end 8 120)
echo "radius: Φ(4.4 µm) = $small, Φ(8 µm) = $large"
above "$small" 0.85 0 || fail "the 4.4 µm cavity should nearly close (Φ = $small)"
above "$small" "$large" 0.3 || fail "Φ should fall by > 0.3 from r = 4.4 to 8 µm ($small, $large)"
soft=$(phi_end 6.2 40) hard=$(phi_end 6.2 360)
echo "yield: Φ(40 MPa) = $soft, Φ(360 MPa) = $hard"
above "$soft" "$hard" 0.25 || fail "Φ should fall by > 0.25 from σ_Y0 = 40 to 360 MPa ($soft, $hard)"
echo "mpm_collapsibility: ok"
