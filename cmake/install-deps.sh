#!/usr/bin/env bash
# Installs the Debian packages listed in cmake/debian-packages.txt that are not installed yet.
# The terminal gets one line per phase (package lists, download, install); apt's and dpkg's own
# output (some 1 800 lines on a fresh machine) goes to a log, CONTACTLAB_DEPS_LOG (default
# build/install-deps.log; `make` passes $(BUILD_DIR)/install-deps.log), whose last lines are
# printed when a phase fails.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
log=${CONTACTLAB_DEPS_LOG:-$here/../build/install-deps.log}
missing=()
while read -r pkg; do
  [[ -z "$pkg" || "$pkg" == \#* ]] && continue
  dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
done < "$here/debian-packages.txt"
if ((${#missing[@]} == 0)); then exit 0; fi

mkdir -p "$(dirname "$log")"
log=$(cd "$(dirname "$log")" && pwd)/$(basename "$log")
echo "contactlab: ${#missing[@]} Debian package(s) missing: ${missing[*]}" > "$log"
echo "contactlab: installing ${#missing[@]} missing Debian package(s); full log: $log"
SUDO=()
if [[ $(id -u) -ne 0 ]]; then SUDO=(sudo); fi

# phase TITLE COMMAND...: one line on the terminal, the command's output in the log.
phase() {
  local title=$1 start=$SECONDS code
  shift
  printf 'contactlab:   %s ... ' "$title"
  printf '\n== %s: %s\n' "$title" "$*" >> "$log"
  if "$@" >> "$log" 2>&1; then
    echo "done ($((SECONDS - start)) s)"
    return 0
  else
    code=$?
  fi
  echo "failed"
  {
    echo "contactlab: error: $title failed (exit code $code); the end of $log:"
    tail -n 25 "$log" | sed 's/^/  /'
  } >&2
  exit "$code"
}

apt() {
  "${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get "$@"
}

phase "updating the package lists" apt update
phase "downloading ${#missing[@]} package(s)" apt install -y --no-install-recommends \
  --download-only "${missing[@]}"
phase "installing ${#missing[@]} package(s)" apt install -y --no-install-recommends "${missing[@]}"
