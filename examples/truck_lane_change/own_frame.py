#!/usr/bin/env python3
"""The truck with its frame as a user's FE model, the seed's workflow
(README.md, "Your own FE frame"): the ladder frame of truck.yaml written as a
Nastran deck, reduced by `flexmb reduce` like any user's deck, and named in a
copy of truck.yaml as `frame: {body, mounts}`.

    python3 own_frame.py --out DIR [--flexmb PATH] [--truck truck.yaml]

writes DIR/frame.bdf, DIR/frame.h5 and DIR/truck_own_frame.yaml (with the
tire files beside it); then

    flexmb run DIR/truck_own_frame.yaml --frame elastic --out RUN

runs the lane change with the frame from the body file. With a frame of your
own, skip the first step: reduce your deck with its mounts' nodes in
--interface and write their ids under `mounts:`.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
# rail geometry that places the mounts (the body file gives the rest)
GEOMETRY = ('front_x', 'length', 'half_spacing', 'web_height', 'bottom_z', 'spider_radius')
# the arm pivots hang about 0.3 m below the frame on their brackets (rigid
# levers): 0.30 m on the 4x2 example, 0.31 m on the more heavily loaded 6x4
MOUNT_TOLERANCE = 0.35


def frame_block(text):
    """(start, end, lines) of the truck's `frame:` map in truck.yaml's text."""
    start = text.index('\n  frame:\n') + 1
    end = start + len('  frame:\n')
    lines = text[end:].split('\n')
    block = []
    for line in lines:
        if line.strip() and not line.startswith('    '):
            break
        block.append(line)
    while block and not block[-1].strip():
        block.pop()
    return start, end + len('\n'.join(block)) + 1, block


def own_frame_file(truck_text, mounts, platform=None, body='frame.h5'):
    """truck.yaml's text with the frame taken from `body` and `mounts`
    [(name, node id)] and, for a frame with a platform, its (spacer,
    sill_height) as the deck gives them; the generated frame's reduction
    keys dropped."""
    start, end, block = frame_block(truck_text)
    top = [l for l in block if not l.startswith('     ')]  # the frame map's own keys, not a platform's
    keep = [l for l in top if l.strip().split(':')[0] in GEOMETRY]
    if platform:
        # the platform is in the deck; its top places the cargo mounts
        keep += [f'    platform: {{spacer: {platform[0]}, sill_height: {platform[1]}}}   # the cargo mounts on its top']
    new = ['  frame:', f'    body: {body}             # flexmb reduce of frame.bdf',
           f'    mount_tolerance: {MOUNT_TOLERANCE}       # m; the arm pivots hang about 0.3 m below the frame on rigid brackets']
    new += keep + ['    mounts:                    # attachment: interface node id of the body file']
    new += [f'      {name}: {node}' for name, node in mounts]
    text = truck_text[:start] + '\n'.join(new) + '\n' + truck_text[end:]
    return re.sub(r'^  frame_(modes|keep_modes|damping|acceleration_modes):.*\n', '', text, flags=re.M)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('--out', required=True, help='folder for frame.bdf, frame.h5 and truck_own_frame.yaml')
    ap.add_argument('--flexmb', default=shutil.which('flexmb') or 'flexmb', help='the flexmb executable')
    ap.add_argument('--truck', default=os.path.join(HERE, 'truck.yaml'), help='lane-change file (default: truck.yaml)')
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    deck = os.path.join(a.out, 'frame.bdf')
    printed = subprocess.run([a.flexmb, 'truck', 'frame-deck', a.truck, '-o', deck], check=True,
                             capture_output=True, text=True).stdout
    # the reduce command frame-deck prints: the lane-change file's modes and damping
    reduce = next(l.split() for l in printed.splitlines() if l.strip().startswith('flexmb reduce'))
    subprocess.run([a.flexmb] + reduce[1:], check=True, capture_output=True)
    deck_text = open(deck).read()
    mounts = re.findall(r'^\$ mount (\w+): node (\d+)$', deck_text, re.M)
    # the platform's placement as the generated frame has it (given or by default)
    platform = re.search(r'^\$ platform: spacer (\S+) sill_height (\S+) ', deck_text, re.M)
    text = open(a.truck).read()
    # the tire files (an axle's `tire:`, or the two-axle form's tires: {front, rear}) beside the new file
    for tire in set(re.findall(r'^\s+(?:-\s+)?(?:front|rear|tire): (\S+\.(?:yaml|tir))', text, re.M)):
        shutil.copy(os.path.join(os.path.dirname(a.truck), tire), a.out)
        text = re.sub(rf'(:\s+){re.escape(tire)}\b', rf'\g<1>{os.path.basename(tire)}', text)
    out = os.path.join(a.out, 'truck_own_frame.yaml')
    with open(out, 'w') as f:
        f.write(own_frame_file(text, mounts, platform.groups() if platform else None))
    print(f'wrote {deck}, {os.path.join(a.out, "frame.h5")} and {out}')


if __name__ == '__main__':
    sys.exit(main())
