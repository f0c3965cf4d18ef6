"""What the Exudyn drivers of bench/peers share: finding the built Exudyn
(EXUDYN_DIR, default bench/peers/exudyn_src), the generalized-alpha settings
of a comparison run, and the timed solve with Exudyn's Newton counters."""
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
EXUDYN_DIR = os.environ.get('EXUDYN_DIR', os.path.join(HERE, 'exudyn_src'))
sys.path.insert(0, os.path.join(EXUDYN_DIR, 'main', 'pythonDev'))


def solve(exu, mbs, args, sensors_period, sparse=False):
    """Generalized-alpha from 0 to args.tend at step args.h (rho_inf args.rho,
    modified Newton if args.modified, EigenSparse if `sparse`), no solution
    file. Returns (integration time [s], step counters of Exudyn's solver)."""
    ss = exu.SimulationSettings()
    steps = int(round(args.tend / args.h))
    ss.timeIntegration.numberOfSteps = steps
    ss.timeIntegration.endTime = args.tend
    ss.timeIntegration.verboseMode = 0
    ss.timeIntegration.generalizedAlpha.spectralRadius = args.rho
    ss.timeIntegration.newton.useModifiedNewton = args.modified
    if sparse:
        ss.linearSolverType = exu.LinearSolverType.EigenSparse
    ss.solutionSettings.writeSolutionToFile = False
    ss.solutionSettings.sensorsWritePeriod = sensors_period
    ss.displayComputationTime = False
    t0 = time.perf_counter()
    mbs.SolveDynamic(ss)
    t_int = time.perf_counter() - t0
    return t_int, mbs.sys['dynamicSolver'].it


def counters(it, t_int, steps):
    """The JSON fields every driver prints: steps, Newton iterations,
    Jacobians, integration time and steps per second."""
    return {'steps': int(it.currentStepIndex), 'newton_iterations': int(it.newtonStepsCount),
            'jacobians': int(it.newtonJacobiCount), 'integration_s': t_int, 'steps_per_s': steps / t_int}


def parser(tend, h, rho, solver_choice=False):
    """The options every driver takes: --modified (modified Newton), --tend,
    --h, --rho with the model's defaults, and with `solver_choice` --solver
    dense|sparse (Exudyn's EXUdense or EigenSparse)."""
    import argparse
    ap = argparse.ArgumentParser()
    ap.add_argument('--modified', action='store_true', help='modified Newton (Jacobian reuse)')
    ap.add_argument('--tend', type=float, default=tend)
    ap.add_argument('--h', type=float, default=h)
    ap.add_argument('--rho', type=float, default=rho)
    if solver_choice:
        ap.add_argument('--solver', default='dense', choices=['dense', 'sparse'],
                        help='Exudyn linear solver: EXUdense (default) or EigenSparse')
    return ap
