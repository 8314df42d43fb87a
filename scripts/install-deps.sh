#!/usr/bin/env bash
# Installs every build, test and run dependency of the OCU from Debian 12 packages.
# Idempotent: when every package is already installed it does nothing (no apt-get update).
set -euo pipefail

packages=(
  cmake g++ make ninja-build ccache git ca-certificates pkg-config
  qt6-base-dev libqt6opengl6-dev qt6-svg-dev qt6-positioning-dev libqt6positioning6-plugins
  qt6-tools-dev qt6-l10n-tools qt6-tools-dev-tools
  libvtk9-dev
  nlohmann-json3-dev libboost-dev libssl-dev openssl
  libgeographiclib-dev libpugixml-dev libsdl2-dev libsqlite3-dev
  libbenchmark-dev
  xvfb xauth libgl1-mesa-dri libglx-mesa0 libegl-dev libegl-mesa0 libglew-dev
  # XInput 2: the STOP ALL press seen off the GUI thread; XTest: bench_stop's real clicks under Xvfb.
  libxi-dev libxtst-dev
  # Fuzzing (scripts/fuzz.sh): clang 14; -fsanitize=fuzzer needs libclang_rt.fuzzer*.a, which Debian 12
  # ships in libclang-rt-14-dev (only a Recommends of clang-14, so not installed by --no-install-recommends).
  clang-14 libclang-rt-14-dev
  # Production charts (Qt Charts, widgets/production) and the shift report test renders the PDF
  # with poppler's pdftoppm.
  qt6-charts-dev poppler-utils
  # GDAL for the 2D map background rasters, the simulated pit's DEM and hillshade, the 3D terrain.
  libgdal-dev
  # Shared control-room history: libpq to build; the server for the tests' throwaway instances.
  libpq-dev postgresql
  # Operator sign-in, switch and unlock through PAM.
  libpam0g-dev
  # PROJ for the coverage report's projected CRS (CSV, GeoTIFF).
  libproj-dev
  # RTSP server + appsrc (dev), x264enc (ugly), rtph264pay/rtspsrc/udp
  # (good), videoconvert (base), avdec_h264 for the tests' RTSP client (libav).
  libgstrtspserver-1.0-dev libgstreamer-plugins-base1.0-dev gstreamer1.0-plugins-base gstreamer1.0-plugins-good
  gstreamer1.0-plugins-ugly gstreamer1.0-libav
  # GStreamer core/app/video dev files and h264parse (bad).
  libgstreamer1.0-dev gstreamer1.0-plugins-bad
  # The flight recorder compresses its machine-state chunks with zstd (docs/recording.md).
  libzstd-dev
  # The Debian package (scripts/package.sh): man pages from --help, dpkg-shlibdeps for its Depends.
  help2man dpkg-dev
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  SUDO="sudo"
fi
echo "install-deps: installing ${#missing[@]} missing packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
