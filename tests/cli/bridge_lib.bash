# Helpers of the bridge tests (bridge.sh, bridge_strength.sh), after lib.bash.
# value FILE DOTTED.KEY: a value of a TOML file.
value() { python3 -c "import tomllib,sys; d=tomllib.load(open(sys.argv[1],'rb'))
for k in sys.argv[2].split('.'): d=d[k]
print(d)" "$1" "$2"; }
# within A B SIGMA N: |A − B| <= N·SIGMA
within() { python3 -c "import sys; a,b,e,n=map(float,sys.argv[1:]); sys.exit(0 if abs(a-b)<=n*e else 1)" "$@"; }
# bad PATTERN... -- ARGS...: refused with exit 2, naming the file and key.
bad() {  # bad PATTERN... -- ARGS...: `shockfield bridge ARGS` fails with exit 2 and every pattern
  local patterns=()
  while [ "$1" != "--" ]; do patterns+=("$1"); shift; done
  shift
  set +e
  "$SF" bridge "$@" > /dev/null 2> "$WORK/err"
  local code=$?
  set -e
  [ $code -eq 2 ] || fail "exit $code for bridge $*: $(cat "$WORK/err")"
  for p in "${patterns[@]}"; do grep -qF -- "$p" "$WORK/err" || fail "message lacks '$p': $(cat "$WORK/err")"; done
  echo "ok: $(head -c 150 "$WORK/err")"
}
