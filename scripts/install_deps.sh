#!/usr/bin/env bash
# Installs every build, run and test dependency of doorplate_localization from Debian 12's own packages.
# --demo: only what scripts/demo.sh needs (it builds the demo's targets only: no MRPT, fuzzing toolchain,
# learned text reader or viewer); a package the demo's targets need belongs in DEMO_PKGS.
# Usage: scripts/install_deps.sh [--demo | --with-viz]   (run as root, or with sudo available)
set -euo pipefail
SUDO=""; [ "$(id -u)" = 0 ] || SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
DEMO_PKGS=(
  # toolchain
  build-essential cmake pkg-config python3 python3-numpy catkin
  # ROS 1 (Debian's own)
  ros-core-dev ros-message-generation ros-message-runtime libroscpp-dev librostest-dev python3-rostest
  python3-roslaunch python3-rostopic python3-rosnode python3-rosbag rosbash rospack-tools
  libnodeletlib-dev libnodeletlib-tools pluginlib-dev libtf2-ros-dev libtf2-geometry-msgs-dev
  libsensor-msgs-dev libnav-msgs-dev libgeometry-msgs-dev libvisualization-msgs-dev libstd-srvs-dev libdiagnostic-msgs-dev
  libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure  # Text AMCL's cfg/TextAmcl.cfg
  librosbag-dev libbz2-dev libroslz4-dev libcv-bridge-dev libimage-transport-dev
  python3-sensor-msgs python3-nav-msgs python3-geometry-msgs python3-tf2-msgs python3-std-msgs python3-std-srvs python3-rosservice
  # core libraries (gtest: the build is configured with its tests, as scripts/test.sh's; CLI11 and nlohmann-json:
  # header-only, the tools' command lines and results files, found by the top CMakeLists.txt, so every build needs them)
  libopencv-dev libtesseract-dev tesseract-ocr-eng libsuitesparse-dev libyaml-cpp-dev libeigen3-dev libgtest-dev
  libcli11-dev nlohmann-json3-dev
  # an optimised BLAS for CHOLMOD's supernodal factorization (the back end's solves; update-alternatives
  # selects it over the reference libblas3: the solves of an hour's patrol 1.3x faster, the last 1.5x,
  # docs/results/back-end-speed.md);
  # serial: the filter and the nodelets use the other core
  libopenblas0-serial
)
PKGS=(
  "${DEMO_PKGS[@]}" catkin-lint libmrpt-dev
  # the learned text reader's install step (scripts/fetch_ocr_models.sh: a throwaway venv from PyPI) and the
  # `tesseract` command (a baseline of bench/real_photos.sh)
  python3-venv tesseract-ocr
  # fuzzing the file parsers (scripts/fuzz.sh): clang with libFuzzer and the sanitizer runtimes
  clang-14 libclang-rt-14-dev llvm-14
  # MRPT's sample datasets: the Málaga rawlog doorplate_map_rawlog maps
  mrpt-common
)
demo=0
case "${1:-}" in
  --with-viz) PKGS+=(rviz xvfb xauth imagemagick);;
  --demo) demo=1; PKGS=("${DEMO_PKGS[@]}");;
  "") ;;
  *) echo "usage: scripts/install_deps.sh [--demo | --with-viz]" >&2; exit 2;;
esac
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${PKGS[@]}"
# roslaunch resolves "localhost" for every local node; a minimal root (container, chroot) may lack it.
if ! getent hosts localhost > /dev/null 2>&1; then
  echo "install_deps: 'localhost' does not resolve; adding '127.0.0.1 localhost' to /etc/hosts (roslaunch needs it)"
  echo "127.0.0.1 localhost" | $SUDO tee -a /etc/hosts > /dev/null
fi
[ "$demo" = 1 ] && exit 0  # the demo reads plates with Tesseract
# The optional learned text reader (PP-OCRv4 models from PyPI's rapidocr-onnxruntime wheel, rewritten for
# OpenCV 4.6). Without PyPI the package still builds and runs on Tesseract; its tests of the learned
# reader are then skipped, saying why.
if ! bash "$(dirname "$0")/fetch_ocr_models.sh"; then
  echo "install_deps: WARNING: the learned text reader's models could not be installed (no PyPI?);" \
       "detector_type:=db / recognizer_type:=ppocr will refuse to start, Tesseract works"
fi
