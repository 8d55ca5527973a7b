# Helpers the whole-process benchmark scripts share (sourced, not run):
#   measure FILE CMD...  runs CMD once under /usr/bin/time -v (its stdout and stderr to
#                        FILE.log and FILE.time) and appends "wall_s cpu_s rss_kib" to FILE;
#                        stops the script with CMD's messages if it fails;
#   median               the median of the numbers on stdin, one per line;
#   machine              "YYYY-MM-DD, <CPU model>, <n> cores", for the line under a table;
#   scene_case FILE      writes the benchmark scene (the elastic (2.5°, 7.5°) wall of Sec. 3,
#                        α⁻ = −12.5°, β⁻ = 0°) as a case file;
#   numpy_python         the `python` of the project's virtual environment (REBOUND_VENV,
#                        default .venv), or stops the script naming the install step.

measure() {
  local file=$1
  shift
  /usr/bin/time -v "$@" > "$file.log" 2> "$file.time" || {
    cat "$file.log" "$file.time" >&2
    exit 1
  }
  awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, p, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + p[i]; w = s}
              /User time/ {u = $2} /System time/ {y = $2}
              /Maximum resident set size/ {r = $2}
              END {print w, u + y, r}' "$file.time" >> "$file"
}

median() {
  sort -g | awk '{a[NR] = $1} END {if (NR == 0) exit 1; print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'
}

machine() {
  local cpu
  cpu=$(awk -F': ' '/^model name/ {print $2; exit}' /proc/cpuinfo 2> /dev/null)
  echo "$(date -u +%F), ${cpu:-unknown CPU}, $(nproc) cores"
}

scene_case() {
  cat > "$1" << 'TOML'
name = "bench-scale"
seed = 1
[wall]
delta_xi_deg = 2.5
delta_zeta_deg = 7.5
[incidence]
alpha_deg = [-12.5]
beta_deg = [0.0]
[particles]
count = 100000
[collision]
model = "elastic"
TOML
}

numpy_python() {
  local venv=${REBOUND_VENV:-.venv}
  "$venv/bin/python" -c "import numpy" 2> /dev/null ||
    { echo "numpy not found in $venv: run scripts/install-deps.sh" >&2; exit 1; }
  echo "$venv/bin/python"
}
