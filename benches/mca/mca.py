#!/usr/bin/env python3
"""Per-iteration cycles of each kernel's innermost loop by llvm-mca, per CPU model.

Usage: mca.py ASSEMBLY.s CPU[,CPU...]
"""
import os, re, shutil, subprocess, sys, tempfile
asm = open(sys.argv[1]).read().splitlines()
cpus = sys.argv[2].split(',')
MCA = shutil.which('llvm-mca') or shutil.which('llvm-mca-14') or sys.exit('llvm-mca not found (apt-get install llvm-14)')
BODY = os.path.join(tempfile.mkdtemp(), 'body.s')
funcs = {}
cur = None
for line in asm:
    m = re.match(r'^([A-Za-z_][\w]*):', line)
    if m and not line.startswith('.'):
        cur = m.group(1); funcs[cur] = []; continue
    if cur: funcs[cur].append(line)
KERNELS = len(sys.argv) > 3 and sys.argv[3] == 'kernels'
def loop_body(lines, main_loop=False):
    labels = {}
    body = []
    for i, l in enumerate(lines):
        m = re.match(r'^(\.LBB\w+):', l)
        if m: labels[m.group(1)] = i
    best = None
    for i, l in enumerate(lines):
        m = re.match(r'\s+j\w+\s+(\.LBB\w+)', l)
        if m and m.group(1) in labels and labels[m.group(1)] < i:
            start = labels[m.group(1)]
            # A one-item loop: its innermost (shortest) loop. A kernel with a tail: its
            # main loop, the longest, not the one-item tail after it.
            longer = best is not None and (i - start) > (best[1]-best[0])
            if best is None or longer == main_loop: best = (start, i)
    if not best: return None
    return [l for l in lines[best[0]+1:best[1]+1] if l.strip() and not l.strip().startswith('.') and not l.strip().startswith('#') and not re.match(r'^\.LBB', l)]
if KERNELS:
    # ga-core's own assembly: the AVX2 copies of the slice kernels.
    names = sorted(f for f in funcs if 'kernels' in f and ('avx' in f or '3x86' in f))
else:
    names = sorted(f for f in funcs if re.match(r"^([bc]|g3|g4)_", f))
print(f"{'kernel':<16}" + ''.join(f"{c:>22}" for c in cpus) + "   uops")
for n in names:
    # The rotor-product kernels take 8 or 16 (f32), 4 or 8 (f64) items a round.
    body = loop_body(funcs[n], main_loop='rotor_product' in n)
    if not body: print(n, 'no loop'); continue
    open(BODY,'w').write('\n'.join(body)+'\n')
    row = f"{n:<16}"
    for c in cpus:
        out = subprocess.run([MCA, f'-mcpu={c}', '-iterations=200', BODY], capture_output=True, text=True).stdout
        if 'Total Cycles' not in out:
            # llvm-mca 14 does not know every AVX-512 instruction.
            row += f"{'not modelled':>22}"; uops = '0'; continue
        cyc = int(re.search(r'Total Cycles:\s+(\d+)', out).group(1)); rt = re.search(r'Block RThroughput:\s+([\d.]+)', out).group(1)
        uops = re.search(r'Total uOps:\s+(\d+)', out).group(1)
        row += f"{cyc/200:>10.1f} cyc (rt {rt:>4})"
    row += f"   {int(uops)//200}"
    print(row)
