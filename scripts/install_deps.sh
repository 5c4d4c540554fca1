#!/usr/bin/env bash
# Installs every build, run and test dependency of doorplate_localization from Debian 12's own packages.
# Usage: scripts/install_deps.sh [--with-viz]   (run as root, or with sudo available)
set -euo pipefail
SUDO=""; [ "$(id -u)" = 0 ] || SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
PKGS=(
  # toolchain
  build-essential cmake pkg-config python3 python3-numpy catkin catkin-lint
  # ROS 1 (Debian's own)
  ros-core-dev ros-message-generation ros-message-runtime libroscpp-dev librostest-dev python3-rostest
  python3-roslaunch python3-rostopic python3-rosnode python3-rosbag rosbash rospack-tools
  libnodeletlib-dev libnodeletlib-tools pluginlib-dev libtf2-ros-dev libtf2-geometry-msgs-dev
  libsensor-msgs-dev libnav-msgs-dev libgeometry-msgs-dev libvisualization-msgs-dev libstd-srvs-dev
  librosbag-dev libcv-bridge-dev libimage-transport-dev
  python3-sensor-msgs python3-nav-msgs python3-geometry-msgs python3-tf2-msgs python3-std-msgs python3-std-srvs python3-rosservice
  # core libraries
  libmrpt-dev libopencv-dev libtesseract-dev tesseract-ocr-eng libsuitesparse-dev libyaml-cpp-dev
  libeigen3-dev libgtest-dev
  # the learned text reader's install step (scripts/fetch_ocr_models.sh: a throwaway venv from PyPI) and the
  # `tesseract` command (a baseline of bench/real_photos.sh)
  python3-venv tesseract-ocr
  # fuzzing the file parsers (scripts/fuzz.sh): clang with libFuzzer and the sanitizer runtimes
  clang-14 libclang-rt-14-dev llvm-14
  # MRPT's sample datasets: the Málaga rawlog doorplate_map_rawlog maps
  mrpt-common
)
if [ "${1:-}" = "--with-viz" ]; then
  PKGS+=(rviz xvfb xauth imagemagick)
fi
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${PKGS[@]}"
# roslaunch resolves "localhost" for every local node; a minimal root (container, chroot) may lack it.
if ! getent hosts localhost > /dev/null 2>&1; then
  echo "install_deps: 'localhost' does not resolve; adding '127.0.0.1 localhost' to /etc/hosts (roslaunch needs it)"
  echo "127.0.0.1 localhost" | $SUDO tee -a /etc/hosts > /dev/null
fi
# The optional learned text reader (PP-OCRv4 models from PyPI's rapidocr-onnxruntime wheel, rewritten for
# OpenCV 4.6). Without PyPI the package still builds and runs on Tesseract; its tests of the learned
# reader are then skipped, saying why.
if ! bash "$(dirname "$0")/fetch_ocr_models.sh"; then
  echo "install_deps: WARNING: the learned text reader's models could not be installed (no PyPI?);" \
       "detector_type:=db / recognizer_type:=ppocr will refuse to start, Tesseract works"
fi
