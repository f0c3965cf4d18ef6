#!/usr/bin/env python3
"""Run the flexmb / Exudyn side-by-side cases, alternating the two codes (A B A B ...),
and append one JSON line per run to OUT/raw.jsonl; summarize.py turns it into tables.

Usage: run_all.py OUT [--cases rotor,ancf,chain,fourbar] [--reps 3] [--quick]
Env (defaults in parentheses):
  FLEXMB      flexmb binary (flexmb on PATH)
  EXUDYN_DIR  Exudyn source tree with the built extension (../exudyn_src next to this folder)
  PYTHON      Python that imports Exudyn's deps (python3)
Each record: code, case, size, newton (full|modified), rep, t_end, steps, newton_iterations,
jacobians/factorizations, integration_s (the code's own integration time), process_wall_s
(whole process, measured here), load1 (1-min load average before the run), response values.
"""
import os, sys, json, time, subprocess, argparse, shutil

HERE = os.path.dirname(os.path.abspath(__file__))
FLEXMB = os.environ.get('FLEXMB', 'flexmb')
PYTHON = os.environ.get('PYTHON', 'python3')
os.environ.setdefault('EXUDYN_DIR', os.path.join(HERE, 'exudyn_src'))
ap = argparse.ArgumentParser()
ap.add_argument('out')
ap.add_argument('--cases', default='rotor,ancf,chain,fourbar')
ap.add_argument('--reps', type=int, default=3)
ap.add_argument('--rotor-modes', default='8,20,50,100')
args = ap.parse_args()
OUT = os.path.abspath(args.out)
os.makedirs(OUT, exist_ok=True)
raw = open(os.path.join(OUT, 'raw.jsonl'), 'a')


def run(cmd, cwd=None):
    load = os.getloadavg()[0]
    t0 = time.perf_counter()
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        print('FAILED:', ' '.join(cmd), '\n', p.stdout[-2000:], p.stderr[-2000:], file=sys.stderr)
    return p, wall, load


def flexmb(model, case, size, newton, rep, t_end=None, extra=None):
    outdir = os.path.join(OUT, 'runs', '%s_%s_%s_r%d' % (case, size, newton, rep))
    shutil.rmtree(outdir, ignore_errors=True)
    cmd = [FLEXMB, 'run', model, '--out', outdir, '--quiet']
    if t_end:
        cmd += ['--t-end', str(t_end)]
    p, wall, load = run(cmd)
    s = json.load(open(os.path.join(outdir, 'summary.json')))
    lines = open(os.path.join(outdir, 'results.csv')).read().strip().split('\n')
    hdr = lines[0].split(','); last = [float(x) for x in lines[-1].split(',')]
    rec = {'code': 'flexmb', 'case': case, 'size': size, 'newton': newton, 'rep': rep, 't_end': s['t_end'],
           'steps': s['steps'], 'newton_iterations': s['newton_iterations'], 'jacobians': s['factorizations'],
           'integration_s': s['integration_time_s'], 'process_wall_s': wall, 'load1': load,
           'response': dict(zip(hdr, last)), 'status': s['status']}
    raw.write(json.dumps(rec) + '\n'); raw.flush()
    return rec


def exudyn(script, argv, case, size, newton, rep):
    p, wall, load = run([PYTHON, os.path.join(HERE, script)] + argv)
    d = json.loads(p.stdout.strip().split('\n')[-1])
    rec = {'code': 'exudyn', 'case': case, 'size': size, 'newton': newton, 'rep': rep,
           'steps': d['steps'] - 1,  # Exudyn's step index counts the initial state
           'newton_iterations': d['newton_iterations'], 'jacobians': d['jacobians'],
           'integration_s': d['integration_s'], 'process_wall_s': wall, 'load1': load, 'detail': d}
    raw.write(json.dumps(rec) + '\n'); raw.flush()
    return rec


cases = args.cases.split(',')
models = os.path.join(OUT, 'models')
if 'ancf' in cases or 'chain' in cases:
    subprocess.run([PYTHON, os.path.join(HERE, 'make_flexmb_models.py'), models], check=True)

if 'rotor' in cases:
    rdir = os.path.join(OUT, 'rotor_models')
    modes = [int(k) for k in args.rotor_modes.split(',')]
    subprocess.run(['sh', os.path.join(HERE, 'rotor', 'make_flexmb_models.sh'), rdir] + [str(k) for k in modes], check=True)
    # Exudyn's FFRF body takes its Jacobian by numerical differentiation: full Newton costs
    # 0.4 s/step at 100 modes, so the long cases run a shorter window (same window for flexmb).
    t_full = {8: 0.5, 20: 0.5, 50: 0.05, 100: 0.02}
    t_mod = {8: 0.5, 20: 0.5, 50: 0.5, 100: 0.1}
    for k in modes:
        for newton, tw in (('full', t_full), ('modified', t_mod)):
            te = tw.get(k, 0.5)
            reps = args.reps if (k, newton) in {(8, 'full'), (8, 'modified'), (20, 'full'), (20, 'modified'), (50, 'full')} else 1
            for rep in range(reps):
                fm = flexmb(os.path.join(rdir, 'rotor%d_reuse_%s.yaml' % (k, 'true' if newton == 'modified' else 'false')),
                            'rotor', k, newton, rep, t_end=te)
                ex = exudyn('rotor/rotor_exudyn.py', ['--modes', str(k), '--tend', str(te)] + (['--modified'] if newton == 'modified' else []),
                            'rotor', k, newton, rep)
                print('rotor K=%d %s rep %d: flexmb %.0f steps/s, exudyn %.1f steps/s' % (
                    k, newton, rep, fm['steps'] / fm['integration_s'], ex['steps'] / ex['integration_s']), flush=True)
    # same frame condition as flexmb (modes M-orthogonal to rigid-body modes): response check
    for k in (8,):
        ex = exudyn('rotor/rotor_exudyn.py', ['--modes', str(k), '--modified', '--mean-axis'], 'rotor_meanaxis', k, 'modified', 0)

if 'ancf' in cases:
    for n in (8, 32, 128):
        for newton in ('full', 'modified'):
            for rep in range(args.reps):
                fm = flexmb(os.path.join(models, 'ancf_N%d_reuse_%s.yaml' % (n, 'true' if newton == 'modified' else 'false')), 'ancf', n, newton, rep)
                ex = exudyn('ancf/ancf_exudyn.py', ['--n', str(n), '--solver', 'dense' if n <= 8 else 'sparse'] + (['--modified'] if newton == 'modified' else []), 'ancf', n, newton, rep)
                print('ancf N=%d %s rep %d: flexmb %.0f, exudyn %.0f steps/s' % (n, newton, rep, fm['steps'] / fm['integration_s'], ex['steps'] / ex['integration_s']), flush=True)

if 'chain' in cases:
    for n in (10, 100, 1000):
        for newton in ('full', 'modified'):
            for rep in range(args.reps):
                fm = flexmb(os.path.join(models, 'chain_N%d_reuse_%s.yaml' % (n, 'true' if newton == 'modified' else 'false')), 'chain', n, newton, rep)
                ex = exudyn('chain/chain_exudyn.py', ['--n', str(n), '--solver', 'sparse'] + (['--modified'] if newton == 'modified' else []), 'chain', n, newton, rep)
                print('chain N=%d %s rep %d: flexmb %.0f, exudyn %.0f steps/s' % (n, newton, rep, fm['steps'] / fm['integration_s'], ex['steps'] / ex['integration_s']), flush=True)

if 'fourbar' in cases:
    # examples/four_bar_2/model.yaml with the comparison's step (1e-3 s) and solver option
    import re
    src = os.path.join(HERE, '..', '..', 'examples', 'four_bar_2', 'model.yaml')
    for newton in ('full', 'modified'):
        m = os.path.join(models, 'four_bar_2_%s.yaml' % newton)
        solver = 'solver: {t_end: 10, dt: 1.0e-3, rho_inf: 0.95%s}' % (', jacobian_reuse: true' if newton == 'modified' else '')
        txt = re.sub(r'^solver:.*$', solver, open(src).read(), flags=re.M)
        os.makedirs(models, exist_ok=True)
        open(m, 'w').write(txt)
        for rep in range(args.reps):
            fm = flexmb(m, 'fourbar', 2, newton, rep)
            ex = exudyn('fourbar/fourbar_exudyn.py', (['--modified'] if newton == 'modified' else []), 'fourbar', 2, newton, rep)
            print('fourbar %s rep %d: flexmb %.0f, exudyn %.0f steps/s' % (newton, rep, fm['steps'] / fm['integration_s'], ex['steps'] / ex['integration_s']), flush=True)
