#!/usr/bin/env python3
"""Tables from OUT/raw.jsonl written by run_all.py.  Usage: summarize.py OUT"""
import sys, os, json, statistics as st
from collections import defaultdict

recs = [json.loads(l) for l in open(os.path.join(sys.argv[1], 'raw.jsonl'))]
g = defaultdict(list)
for r in recs:
    g[(r['case'], r['size'], r['newton'], r['code'])].append(r)


def med(rs, f):
    return st.median([f(r) for r in rs])


def resp(case, r):
    if r['code'] == 'flexmb':
        d = r['response']
        if case == 'rotor':
            return 'mid (%.3e, %.3e) unb (%.6f, %.6f)' % (d['mid.x'], d['mid.y'], d['unb.x'], d['unb.y'])
        if case == 'ancf':
            return 'tip (%.5f, %.5f)' % (d['tip.x'], d['tip.y'])
        if case == 'chain':
            return 'end (%.6f, %.6f)' % (d['end.x'], d['end.y'])
        if case == 'fourbar':
            return 'B0 (%.8f, %.8f)' % (d['b0.x'], d['b0.y'])
    d = r['detail']
    if case.startswith('rotor'):
        return 'mid (%.3e, %.3e) unb (%.6f, %.6f)' % (d['mid_node_pos'][0], d['mid_node_pos'][1], d['unbalance_node_pos'][0], d['unbalance_node_pos'][1])
    if case == 'ancf':
        return 'tip (%.5f, %.5f)' % tuple(d['tip'])
    if case == 'chain':
        return 'end (%.6f, %.6f)' % tuple(d['end'][:2])
    if case == 'fourbar':
        return 'B0 (%.8f, %.8f)' % tuple(d['b0'])


keys = sorted({(c, s, n) for (c, s, n, _) in g}, key=lambda k: (k[0], k[1], k[2]))
print('| case | size | Newton | t_end | flexmb steps/s | Exudyn steps/s | ratio F/E | flexmb it/step (fact./step) | Exudyn it/step (jac./step) | process wall F / E [s] | load1 | runs | flexmb response | Exudyn response |')
print('|---|---|---|---|---|---|---|---|---|---|---|---|---|---|')
for (c, s, n) in keys:
    F = g.get((c, s, n, 'flexmb'), []); E = g.get((c, s, n, 'exudyn'), [])
    if not F or not E:
        continue
    fs = med(F, lambda r: r['steps'] / r['integration_s']); es = med(E, lambda r: r['steps'] / r['integration_s'])
    fit = med(F, lambda r: r['newton_iterations'] / r['steps']); eit = med(E, lambda r: r['newton_iterations'] / r['steps'])
    fj = med(F, lambda r: r['jacobians'] / r['steps']); ej = med(E, lambda r: r['jacobians'] / r['steps'])
    fw = med(F, lambda r: r['process_wall_s']); ew = med(E, lambda r: r['process_wall_s'])
    load = st.median([r['load1'] for r in F + E])
    te = F[0].get('t_end', '')
    print('| %s | %s | %s | %s | %.4g | %.4g | %.3g | %.2f (%.2f) | %.2f (%.3f) | %.3g / %.3g | %.2f | %d/%d | %s | %s |' % (
        c, s, n, te, fs, es, fs / es, fit, fj, eit, ej, fw, ew, load, len(F), len(E), resp(c, F[-1]), resp(c, E[-1])))
for (c, s, n, code), rs in sorted(g.items()):
    if c == 'rotor_meanaxis':
        print('\nExudyn, modes M-orthogonal to rigid-body modes (flexmb frame condition), K=%s %s: %s' % (s, n, resp(c, rs[-1])))
fr = [(r['size'], r['detail']['freq_hz_reduced_freefree'][:4]) for r in recs if r['code'] == 'exudyn' and r['case'] == 'rotor' and r['rep'] == 0 and r['newton'] == 'full']
if fr:
    print('\nExudyn reduced free-free frequencies [Hz]:')
    for k, f in fr:
        print('  K=%s: %s' % (k, ', '.join('%.6f' % x for x in f)))

# best against best: each code's faster Newton variant (median), and full Newton alone;
# the rigid chain also against Chrono's figures measured earlier on this machine kind
# (issue 23: ChLinkMate joints, HHT; N = 10 / 100 / 1000)
CHRONO_CHAIN = {10: 11160.0, 100: 964.0, 1000: 82.0}
print('\n| case | size | flexmb best [steps/s] | Exudyn best [steps/s] | best / best | flexmb full / Exudyn full | goal |')
print('|---|---|---|---|---|---|---|')
for (c, s) in sorted({(k[0], k[1]) for k in keys}):
    def rate(code, n):
        rs = g.get((c, s, n, code), [])
        return med(rs, lambda r: r['steps'] / r['integration_s']) if rs else float('nan')
    if not g.get((c, s, 'full', 'flexmb')) or not g.get((c, s, 'full', 'exudyn')):
        continue
    fb = max(rate('flexmb', 'full'), rate('flexmb', 'modified'))
    eb = max(rate('exudyn', 'full'), rate('exudyn', 'modified'))
    ff = rate('flexmb', 'full') / rate('exudyn', 'full')
    goal = ''
    if c == 'ancf':
        goal = '>= 2 (N = 128)' if int(s) == 128 else '>= 1'
    elif c == 'chain':
        goal = 'flexmb best / (5 x Chrono %g) = %.2f' % (CHRONO_CHAIN[int(s)], fb / (5 * CHRONO_CHAIN[int(s)]))
    elif c == 'rotor' and int(s) == 100:
        goal = 'flexmb full / 5000 = %.2f' % (rate('flexmb', 'full') / 5000.0)
    print('| %s | %s | %.4g | %.4g | %.3g | %.3g | %s |' % (c, s, fb, eb, fb / eb, ff, goal))
