#!/usr/bin/env bash
# Installs what cambrian needs on Debian 12, from Debian's archive, and the browser viewer's npm
# packages from viewer/package-lock.json (npm ci), then bundles the viewer. Idempotent: packages
# already present are not touched, apt-get runs only when something is missing, npm ci only when
# the lock file changed since the last install.
set -euo pipefail
cd "$(dirname "$0")/../.."

packages=(
  build-essential cmake ninja-build pkg-config git clang-format
  clang libclang-rt-14-dev llvm
  libbullet-dev libbullet-extras-dev
  libopenmpi-dev openmpi-bin
  libhdf5-dev hdf5-tools
  libboost-program-options-dev libboost-dev
  googletest libgtest-dev
  librandom123-dev
  python3 python3-h5py python3-numpy python3-matplotlib python3-pytest python3-pil python3-pandas
  slurm-wlm slurm-client munge
  chromium
)

# which packages are missing
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

# node and npm: Debian's, unless the commands are there already (a NodeSource nodejs has npm)
command -v node >/dev/null 2>&1 || missing+=(nodejs)
command -v npm >/dev/null 2>&1 || missing+=(npm)

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
else
  # install them (root, or through sudo)
  echo "install-deps: installing ${missing[*]}"
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}"
fi

# the viewer: three.js and esbuild exactly as the lock file pins them, then its bundle
stamp=viewer/node_modules/.cambrian-lock
if ! cmp -s viewer/package-lock.json "$stamp"; then
  echo "install-deps: npm ci in viewer/"
  (cd viewer && npm ci --no-audit --no-fund --loglevel=error)
  cp viewer/package-lock.json "$stamp"
fi
(cd viewer && npm run --silent build -- --log-level=warning)
