#!/usr/bin/env bash
# rviz screenshot test (headless): runs launch/localization.launch with rviz (rviz/localization.rviz) on the
# 15.5 m corridor under Xvfb with software GL, takes screenshots of the whole screen until the particle cloud
# and the text-landmark markers are both seen drawn (test/viz/count_colors.py), at most TIMEOUT_S seconds.
# Needs rviz, xvfb and imagemagick (scripts/install_deps.sh --with-viz). Run from scripts/test.sh, or:
#   bash test/viz/rviz_screenshot_test.sh [BUILD_DIR] [OUT_DIR]
# Prints "viz: 1 passed, 0 failed" (or 0 passed, 1 failed) as its last line; keeps the last screenshot.
set -uo pipefail
repo="$(cd "$(dirname "$0")/../.." && pwd)"
inner=0
[ "${1:-}" = "--inner" ] && { inner=1; shift; }  # the part that runs inside Xvfb
build="${1:-${DOORPLATE_BUILD:-$repo/build}}"
out="${2:-$build/test_results/viz}"
timeout_s="${RVIZ_TEST_TIMEOUT_S:-180}"
mkdir -p "$out"
for tool in rviz xvfb-run import; do
  command -v "$tool" > /dev/null || { echo "[viz] $tool not installed (scripts/install_deps.sh --with-viz)"; echo "viz: 0 passed, 1 failed"; exit 1; }
done
source "$repo/scripts/env.sh" "$build" > /dev/null
source "$build/devel/setup.bash"
port=$((20000 + RANDOM % 10000))
export ROS_MASTER_URI="http://127.0.0.1:$port" LIBGL_ALWAYS_SOFTWARE=1

if [ "$inner" = 1 ]; then
  roslaunch -p "$port" doorplate_localization localization.launch world_name:=paper_sim_closed_doors rviz:=true \
    real_time_factor:=1 > "$out/roslaunch.log" 2>&1 &
  launch_pid=$!; deadline=$((SECONDS + timeout_s)); verdict=""
  while [ $SECONDS -lt $deadline ]; do
    sleep 2
    kill -0 "$launch_pid" 2>/dev/null || { echo "[viz] roslaunch exited early"; tail -n 20 "$out/roslaunch.log"; break; }
    import -window root -depth 8 "$out/screen.ppm" 2>/dev/null || continue
    verdict=$(/usr/bin/python3 "$repo/test/viz/count_colors.py" "$out/screen.ppm")
    if [[ "$verdict" == ok* ]]; then break; fi
  done
  if [[ "$verdict" != ok* ]]; then  # say why: was anything published, did a node complain?
    for topic in /particlecloud /text_landmarks /amcl/state; do
      echo "[viz] $topic: $(timeout 5 rostopic info "$topic" 2>&1 | grep -c '^ \* ') publishers/subscribers listed"
    done
    echo "[viz] last lines of $out/roslaunch.log:"; tail -n 20 "$out/roslaunch.log"
  fi
  kill -INT "$launch_pid" 2>/dev/null; wait "$launch_pid" 2>/dev/null
  echo "[viz] $verdict after $((SECONDS - deadline + timeout_s)) s (screenshot: $out/screen.png)"
  convert "$out/screen.ppm" "$out/screen.png" 2>/dev/null
  [[ "$verdict" == ok* ]]
  exit
fi
if xvfb-run -a -s "-screen 0 1600x1000x24" bash "$0" --inner "$build" "$out"; then
  echo "viz: 1 passed, 0 failed"
else
  echo "viz: 0 passed, 1 failed"; exit 1
fi
