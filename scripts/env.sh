# Source this (bash) to get the environment the package needs on Debian 12's own ROS 1:
# Debian's python3 before pyenv shims (catkin's cmake helpers import Debian's python3 modules),
# system packages on ROS_PACKAGE_PATH, one OpenMP thread for Tesseract.
# Usage: source scripts/env.sh [BUILD_DIR]   (BUILD_DIR defaults to <repo>/build)
_dl_repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export DOORPLATE_REPO="$_dl_repo"
export DOORPLATE_BUILD="${1:-${DOORPLATE_BUILD:-$_dl_repo/build}}"
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"
export OMP_THREAD_LIMIT=1
export ROS_PYTHON_VERSION=3
export ROS_DISTRO="${ROS_DISTRO:-Debian}"  # the value /etc/catkin/profile.d/1.ros_distro.sh expects
# Local ROS graph. A minimal root without /etc/hosts cannot resolve "localhost": use the loopback address.
if getent hosts localhost > /dev/null 2>&1; then _dl_host=localhost; else _dl_host=127.0.0.1; fi
export ROS_MASTER_URI="${ROS_MASTER_URI:-http://$_dl_host:11311}"
export ROS_HOSTNAME="${ROS_HOSTNAME:-$_dl_host}"
unset _dl_host
export ROS_HOME="${ROS_HOME:-$DOORPLATE_BUILD/ros_home}"
if [ -f "$DOORPLATE_BUILD/devel/setup.bash" ]; then
  # shellcheck disable=SC1091
  source "$DOORPLATE_BUILD/devel/setup.bash"
fi
# rospack must find this package (its folder) and Debian's ROS packages (/usr/share/<pkg>).
case ":${ROS_PACKAGE_PATH:-}:" in *":$_dl_repo:"*) ;; *) export ROS_PACKAGE_PATH="$_dl_repo:${ROS_PACKAGE_PATH:-}";; esac
case ":$ROS_PACKAGE_PATH:" in *":/usr/share:"*) ;; *) export ROS_PACKAGE_PATH="$ROS_PACKAGE_PATH:/usr/share";; esac
export ROS_PACKAGE_PATH="${ROS_PACKAGE_PATH#:}"
unset _dl_repo
