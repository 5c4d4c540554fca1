# Merges the per-part JSON files of a split `doorplate_eval goto` run (--first-trial) and prints the figures of
# docs/results/floor-goto.md: python3 merge_parts.py part0.json part1.json ...
import json, statistics as st, sys, math
trials = []
for f in sys.argv[1:]:
    trials += json.load(open(f))['trials']
trials.sort(key=lambda t: t['index'])
n = len(trials)
succ = sum(t['success'] for t in trials)
print('trials', n, 'success', succ, 'arrived', sum(t['arrived'] for t in trials), 'bumped', sum(t['bumped'] for t in trials))
d = [t['distance_m'] for t in trials]
print('dist median %.3f max %.3f' % (st.median(d), max(d)))
print('along max %.3f across %.3f..%.3f' % (max(abs(t['along_m']) for t in trials), min(t['across_m'] for t in trials), max(t['across_m'] for t in trials)))
y = [abs(t['yaw_error_rad']) * 180 / math.pi for t in trials]
print('yaw median %.1f max %.1f' % (st.median(y), max(y)))
tr = [t['travel_m'] for t in trials]
print('travel median %.1f max %.1f' % (st.median(tr), max(tr)))
print('sim median %.0f' % st.median(t['sim_seconds'] for t in trials))
ps = [t['plan_seconds'] for t in trials]
print('plan median %.3f max %.3f' % (st.median(ps), max(ps)))
print('replans', sum(t['replans'] for t in trials))
print('est median %.3f max %.3f' % (st.median(t['estimate_error_m'] for t in trials), max(t['estimate_error_m'] for t in trials)))
print('plate updates median', st.median(t['plate_updates'] for t in trials))
print('wall s total %.0f' % sum(t['wall_seconds'] for t in trials))
for t in trials:
    if not t['success']: print('FAIL', t['index'], t['room'], t['outcome'], t['distance_m'])
