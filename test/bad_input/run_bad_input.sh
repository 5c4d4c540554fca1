#!/usr/bin/env bash
# The bad-input corpus of the offline tools (issue 18; docs/reliability.md, "Bad-input corpus"): every case
# runs one built tool on an absurd or broken input (the files of test/bad_input/, copied into a fresh folder
# of its own) and passes only if
#   - the exit status is the expected one (1: bad input, 2: bad command line; never a signal or 0),
#   - the output (stdout + stderr) matches the case's regex: the error names the file, field or option,
#   - the output holds no crash or library backtrace (terminate, bad_alloc, a sanitizer, MRPT's call stack),
#   - every file of the case's folder has the same bytes afterwards (the inputs, and the earlier "good"
#     output some cases put there first) and no file was added: nothing was written.
# A tool that is not built (MRPT's, when MRPT is missing) is skipped and said so.
# Usage: bash test/bad_input/run_bad_input.sh [BUILD_DIR]   (scripts/test.sh runs it)
# Prints one line per case and "bad_input: N passed, M failed" as its last line; exits 1 on a failure.
set -uo pipefail
repo="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:-${DOORPLATE_BUILD:-$repo/build}}"
bin="$build/devel/lib/doorplate_localization"
corpus="$repo/test/bad_input"
[ -f "$build/devel/setup.bash" ] && source "$repo/scripts/env.sh" "$build" > /dev/null
export OMP_THREAD_LIMIT=1
work="$(mktemp -d "${TMPDIR:-/tmp}/doorplate_bad_input.XXXXXX")"
trap 'rm -rf "$work"' EXIT
passed=0; failed=0; skipped=0; case_dir=""; case_name=""
# A crash or a library's backtrace in what a user sees.
forbidden='terminate called|std::bad_alloc|Segmentation fault|core dumped|AddressSanitizer|runtime error:|Aborted|MRPT exception|Call stack|Stack trace|backtrace'

# begin NAME FILE...: a fresh folder for case NAME holding copies of the corpus FILEs; the case runs in it.
begin() {
  case_name="$1"; shift
  case_dir="$work/$case_name"
  mkdir -p "$case_dir"
  for f in "$@"; do cp "$corpus/$f" "$case_dir/"; done
  cd "$case_dir" || exit 1
}

snapshot() { (cd "$case_dir" && find . -type f -print0 | sort -z | xargs -0 -r md5sum); }

# expect STATUS REGEX TOOL ARG...: runs the tool (at most 60 s) in the case folder and checks it.
expect() {
  local status="$1" regex="$2" tool="$3"; shift 3
  if [ ! -x "$bin/$tool" ]; then
    skipped=$((skipped + 1)); echo "[bad_input] $case_name: skipped ($tool is not built)"; return
  fi
  local before after out rc start problems=()
  before="$(snapshot)"
  start=$SECONDS
  out="$(timeout 60 "$bin/$tool" "$@" 2>&1)"; rc=$?
  after="$(snapshot)"
  [ "$rc" = "$status" ] || problems+=("exit status $rc, expected $status")
  grep -Eq -- "$regex" <<< "$out" || problems+=("output does not match /$regex/")
  ! grep -Eq -- "$forbidden" <<< "$out" || problems+=("crash or backtrace in the output")
  [ "$before" = "$after" ] || problems+=("files changed: $(diff <(echo "$before") <(echo "$after") | grep '^[<>]' | tr '\n' ' ')")
  if [ ${#problems[@]} = 0 ]; then
    passed=$((passed + 1))
    echo "[bad_input] $case_name: ok ($((SECONDS - start)) s): $(grep -E -m1 -- "$regex" <<< "$out" | cut -c1-200)"
  else
    failed=$((failed + 1))
    echo "[bad_input] $case_name: FAILED ($((SECONDS - start)) s): $(IFS=';'; echo "${problems[*]}")"
    echo "    command: $tool $*"
    tail -n 15 <<< "$out" | cut -c1-300 | sed 's/^/    | /'
  fi
}

# A "good" earlier result in OUT_DIR, which a refused run must leave as it was.
earlier_result() { mkdir -p "$1"; printf 'P5\n2 1\n255\n\0\376' > "$1/map.pgm"; printf 'image: map.pgm\n' > "$1/map.yaml"; }

# world_maps_of WORLD BASE: the world's ground-truth maps BASE.{pgm,yaml,text_map.yaml}, for a case that needs
# good maps beside its bad input.
world_maps_of() { "$bin/doorplate_world_maps" --world "$1" --out "$2" > /dev/null 2>&1; }

# ---- doorplate_map_log (CARMEN logs) ----
begin map_log_poses_shifted_1e15 carmen_shifted_1e15.log; earlier_result out
expect 1 'carmen_shifted_1e15\.log:2: laser pose x: must be finite and within \+-1e\+06 m \(limits::kMaxCoordinateM\), got 1e\+15' doorplate_map_log --log carmen_shifted_1e15.log --out out
begin map_log_all_ranges_minus_1 carmen_all_ranges_minus1.log; earlier_result out
expect 1 'carmen_all_ranges_minus1\.log: the run produced no usable map' doorplate_map_log --log carmen_all_ranges_minus1.log --out out
begin map_log_ranges_1e308_poses_1e300 carmen_ranges_1e308_poses_1e300.log; earlier_result out
expect 1 'carmen_ranges_1e308_poses_1e300\.log:2: range 0: 1e308 does not fit a float range' doorplate_map_log --log carmen_ranges_1e308_poses_1e300.log --out out
begin map_log_line_missing_a_beam carmen_missing_beam.log; earlier_result out
expect 1 'carmen_missing_beam\.log:7: .*180 beams' doorplate_map_log --log carmen_missing_beam.log --out out
begin map_log_particles_1e9 carmen_ok.log
expect 2 '--particles: .1e9. is not a whole number in' doorplate_map_log --log carmen_ok.log --out out --particles 1e9
begin map_log_set_num_particles_1e9 carmen_ok.log
expect 1 'num_particles: must be in \[1, 1000000\] \(limits::kMaxParticles\), got 1000000000' doorplate_map_log --log carmen_ok.log --out out --set num_particles=1000000000
begin map_log_out_over_its_log carmen_ok.log; mkdir out; mv carmen_ok.log out/trajectory.txt
expect 1 'would write out/trajectory\.txt, the input given to --log' doorplate_map_log --log out/trajectory.txt --out out
begin map_log_missing_log
expect 1 'no_such\.log' doorplate_map_log --log no_such.log --out out
begin map_log_gzipped_garbage garbage.log.gz
expect 1 'garbage\.log\.gz: no FLASER lines \(a \.gz log must be unpacked first\)' doorplate_map_log --log garbage.log.gz --out out

# ---- doorplate_map_rawlog (MRPT rawlogs) ----
begin map_rawlog_garbage garbage.rawlog; earlier_result out
expect 1 'garbage\.rawlog: not an MRPT rawlog MRPT can read: entry 0: ' doorplate_map_rawlog garbage.rawlog --out-dir out
begin map_rawlog_carmen_log_given carmen_ok.log; earlier_result out
expect 1 'carmen_ok\.log: not an MRPT rawlog MRPT can read: entry 0: ' doorplate_map_rawlog carmen_ok.log --out-dir out
begin map_rawlog_empty_file; : > empty.rawlog
expect 1 'empty\.rawlog: an empty rawlog' doorplate_map_rawlog empty.rawlog --out-dir out
begin map_rawlog_missing_file
expect 1 'no_such\.rawlog: no such file' doorplate_map_rawlog no_such.rawlog --out-dir out
begin map_rawlog_out_over_its_rawlog garbage.rawlog; mkdir out; mv garbage.rawlog out/map.pgm
expect 1 'would write out/map\.pgm, the input given to RAWLOG' doorplate_map_rawlog out/map.pgm --out-dir out

# ---- doorplate_map_bag (rosbags) ----
begin map_bag_garbage garbage.bag; earlier_result out
expect 1 'garbage\.bag: not a readable bag: Error reading version line' doorplate_map_bag garbage.bag --out-dir out
begin map_bag_header_then_garbage bag_header_then_garbage.bag; earlier_result out
expect 1 'bag_header_then_garbage\.bag: not a readable bag: ' doorplate_map_bag bag_header_then_garbage.bag --out-dir out
begin map_bag_tf_count_beyond_the_message tf_claims_4294967294_transforms.bag; earlier_result out
expect 1 'tf_claims_4294967294_transforms\.bag: not a readable bag: topic /tf, message at 10\.000 s: tf2_msgs/TFMessage\.transforms: 4294967294 elements of at least 76 bytes, but 89 bytes follow' doorplate_map_bag tf_claims_4294967294_transforms.bag --out-dir out
begin map_bag_version_line_longer_than_rosbag_reads version_line_of_1112_bytes.bag; earlier_result out
expect 1 'version_line_of_1112_bytes\.bag: not a readable bag: record at byte 1023: header length 538976288, but only [0-9]+ bytes follow' doorplate_map_bag version_line_of_1112_bytes.bag --out-dir out
begin map_bag_message_past_its_compressed_chunk bz2_message_data_beyond_chunk.bag; earlier_result out
expect 1 'bz2_message_data_beyond_chunk\.bag: not a readable bag: chunk at byte 4117: record at byte 2255: data length 200000, but only 8591 bytes follow' doorplate_map_bag bz2_message_data_beyond_chunk.bag --out-dir out
begin map_bag_index_count_beyond_its_data index_count_one_more.bag; earlier_result out
expect 1 'index_count_one_more\.bag: not a readable bag: record at byte 15058: index data: count 2 \(2 × 12 bytes\), but its data has 12 bytes' doorplate_map_bag index_count_one_more.bag --out-dir out
begin map_bag_encryptor_plugin_not_installed encryptor_plugin_not_installed.bag; earlier_result out
expect 1 'encryptor_plugin_not_installed\.bag: not a readable bag: its header names an encryptor plugin that cannot be loaded: .*class nope' doorplate_map_bag encryptor_plugin_not_installed.bag --out-dir out
begin map_bag_missing_bag
expect 1 'no_such\.bag' doorplate_map_bag no_such.bag --out-dir out
begin map_bag_out_over_its_bag garbage.bag; mkdir out; mv garbage.bag out/map.pgm
expect 1 'would write out/map\.pgm, the input given to BAG' doorplate_map_bag out/map.pgm --out-dir out
begin map_bag_particles_1e9 garbage.bag
expect 1 'num_particles: must be in \[1, 1000000\] \(limits::kMaxParticles\)' doorplate_map_bag garbage.bag --out-dir out --set num_particles=1000000000

# ---- doorplate_world_maps ----
begin world_maps_out_over_its_world world_ok.yaml
expect 1 'would write world_ok\.yaml, the input given to --world' doorplate_world_maps --world world_ok.yaml --out world_ok
begin world_maps_start_x_1e300 world_start_1e300.yaml
expect 1 'world_start_1e300\.yaml: robot\.start\.x_m' doorplate_world_maps --world world_start_1e300.yaml --out m
begin world_maps_crossing_walls world_crossing_walls.yaml
expect 1 'world_crossing_walls\.yaml: .*crosses wall' doorplate_world_maps --world world_crossing_walls.yaml --out m
begin world_maps_overlapping_walls world_overlapping_walls.yaml
expect 1 'world_overlapping_walls\.yaml: .*lies on wall' doorplate_world_maps --world world_overlapping_walls.yaml --out m
begin world_maps_resolution_1e-9 world_ok.yaml
expect 2 '--resolution: must be finite and in \[0\.001, 100\] m \(limits::kMinMapResolutionM, kMaxMapResolutionM\), got 1e-09' doorplate_world_maps --world world_ok.yaml --out m --resolution 1e-9
begin world_maps_resolution_1e3 world_ok.yaml
expect 2 '--resolution: must be finite .* got 1000' doorplate_world_maps --world world_ok.yaml --out m --resolution 1e3
begin world_maps_missing_world
expect 1 'no_such\.yaml' doorplate_world_maps --world no_such.yaml --out m

# ---- doorplate_sim_snapshot ----
begin sim_snapshot_camera_over_its_world world_ok.yaml; mv world_ok.yaml W.png
expect 1 'would write W\.png, the input given to --world' doorplate_sim_snapshot --world W.png --camera W.png
begin sim_snapshot_start_x_1e300 world_start_1e300.yaml
expect 1 'world_start_1e300\.yaml: robot\.start\.x_m' doorplate_sim_snapshot --world world_start_1e300.yaml --camera c.png
begin sim_snapshot_pose_x_1e300 world_ok.yaml
expect 1 '--x: must be finite and within \+-1e\+06 m \(limits::kMaxCoordinateM\), got 1e\+300' doorplate_sim_snapshot --world world_ok.yaml --camera c.png --x 1e300 --y 1 --theta 0
begin sim_snapshot_crossing_walls world_crossing_walls.yaml
expect 1 'world_crossing_walls\.yaml: .*crosses wall' doorplate_sim_snapshot --world world_crossing_walls.yaml --camera c.png

# ---- doorplate_photo_world ----
begin photo_world_short_tsv_line crops_short_line.tsv
expect 1 'crops_short_line\.tsv:3' doorplate_photo_world --crops crops_short_line.tsv --out out
begin photo_world_missing_photo crops_missing_photo.tsv
expect 1 'doorplate_photo_world: crops_missing_photo\.tsv:2: cannot read image .no_such_photo\.png.' doorplate_photo_world --crops crops_missing_photo.tsv --out out
begin photo_world_out_over_its_crops crops_short_line.tsv; mkdir -p out/worlds; mv crops_short_line.tsv out/worlds/photo_plates.yaml
expect 1 'would write .*photo_plates\.yaml, the input given to --crops' doorplate_photo_world --crops out/worlds/photo_plates.yaml --out out

# ---- doorplate_read_image ----
begin read_image_not_an_image not_an_image.png
expect 1 'not_an_image\.png: not an image' doorplate_read_image not_an_image.png
begin read_image_pgm_20000x20000 map_20000x20000.pgm
expect 1 'doorplate_read_image: map_20000x20000\.pgm: not an image OpenCV can read' doorplate_read_image map_20000x20000.pgm
begin read_image_json_over_its_image not_an_image.png
expect 1 'would write not_an_image\.png, the input given to IMAGE' doorplate_read_image --json not_an_image.png not_an_image.png
begin read_image_missing_models not_an_image.png
expect 1 'no_models' doorplate_read_image --detector db --model-dir no_models not_an_image.png

# ---- doorplate_eval ----
begin eval_localize_map_20000x20000 world_ok.yaml text_map_huge_grid.yaml map_20000x20000.yaml map_20000x20000.pgm
expect 1 'map_20000x20000\.pgm: header: size 20000 x 20000' doorplate_eval localize --world world_ok.yaml --map text_map_huge_grid.yaml --trials 1
begin eval_localize_max_particles_1e9 world_ok.yaml; world_maps_of world_ok.yaml ok
expect 1 'max_particles: must be <= 1000000 \(limits::kMaxParticles\), got 1000000000' doorplate_eval localize --world world_ok.yaml --map ok.text_map.yaml --max-particles 1e9 --trials 1
begin eval_localize_start_x_1e300 world_start_1e300.yaml
expect 1 'world_start_1e300\.yaml: robot\.start\.x_m' doorplate_eval localize --world world_start_1e300.yaml --trials 1
begin eval_map_particles_1e9 world_ok.yaml
expect 1 'num_particles: must be in \[1, 1000000\] \(limits::kMaxParticles\), got 1000000000' doorplate_eval map --world world_ok.yaml --particles 1e9 --max-seconds 1
begin eval_map_json_over_its_world world_ok.yaml
expect 2 'would write world_ok\.yaml, the input given to --world' doorplate_eval map --world world_ok.yaml --json world_ok.yaml --max-seconds 1
begin eval_localize_json_over_its_map world_ok.yaml; world_maps_of world_ok.yaml ok
expect 2 'would write ok\.text_map\.yaml, the input given to --map' doorplate_eval localize --world world_ok.yaml --map ok.text_map.yaml --json ok.text_map.yaml --trials 1
begin eval_ocr_json_over_its_world world_ok.yaml
expect 2 'would write world_ok\.yaml, the input given to --world' doorplate_eval ocr --world world_ok.yaml --json world_ok.yaml
begin eval_map_crossing_walls world_crossing_walls.yaml
expect 1 'world_crossing_walls\.yaml: .*crosses wall' doorplate_eval map --world world_crossing_walls.yaml --max-seconds 1

# ---- doorplate_soak ----
begin soak_particles_1e9 world_ok.yaml
expect 1 'KldSampler: max_particles: must be <= 1000000 \(limits::kMaxParticles\), got 1000000000' doorplate_soak --world world_ok.yaml --seconds 1 --window 1 --particles 1e9
begin soak_markdown_over_its_world world_ok.yaml
expect 1 'would write world_ok\.yaml, the input given to --world' doorplate_soak --world world_ok.yaml --seconds 1 --window 1 --markdown world_ok.yaml
begin soak_start_x_1e300 world_start_1e300.yaml
expect 1 'world_start_1e300\.yaml: robot\.start\.x_m' doorplate_soak --world world_start_1e300.yaml --seconds 1 --window 1

# ---- doorplate_laser_fit ----
begin laser_fit_line_missing_a_beam carmen_missing_beam.log
expect 1 'carmen_missing_beam\.log:7: ' doorplate_laser_fit --log carmen_missing_beam.log
begin laser_fit_gzipped_garbage garbage.log.gz
expect 1 'garbage\.log\.gz' doorplate_laser_fit --log garbage.log.gz
begin laser_fit_poses_shifted_1e15 carmen_shifted_1e15.log
expect 1 'carmen_shifted_1e15\.log:2: laser pose x: .*kMaxCoordinateM' doorplate_laser_fit --log carmen_shifted_1e15.log
begin laser_fit_json_over_its_log carmen_ok.log
expect 1 'would write carmen_ok\.log, the input given to --log' doorplate_laser_fit --log carmen_ok.log --json carmen_ok.log

# ---- doorplate_odometry_fit ----
begin odometry_fit_garbage garbage.rawlog
expect 1 'garbage\.rawlog: not an MRPT rawlog MRPT can read: entry 0: ' doorplate_odometry_fit --rawlog garbage.rawlog --json out.json
begin odometry_fit_json_over_its_rawlog garbage.rawlog
expect 1 'would write garbage\.rawlog, the input given to --rawlog' doorplate_odometry_fit --rawlog garbage.rawlog --json garbage.rawlog

# ---- doorplate_mission_report ----
begin mission_report_garbage_bags world_ok.yaml garbage.bag; world_maps_of world_ok.yaml map; earlier_result out
expect 1 'garbage\.bag: not a readable bag: ' doorplate_mission_report --world world_ok.yaml --maps . --mapping-bag garbage.bag --localization-bag garbage.bag --room 202 --out out
begin mission_report_bad_command_line world_ok.yaml
expect 2 '[Uu]sage: doorplate_mission_report' doorplate_mission_report --world world_ok.yaml --room

cd "$repo" || exit 1
[ "$skipped" = 0 ] || echo "[bad_input] $skipped case(s) skipped (tool not built)"
echo "bad_input: $passed passed, $failed failed"
[ "$failed" = 0 ]
