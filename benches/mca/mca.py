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
def loop_body(lines):
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
            if best is None or (i - start) < (best[1]-best[0]): best = (start, i)
    if not best: return None
    return [l for l in lines[best[0]+1:best[1]+1] if l.strip() and not l.strip().startswith('.') and not l.strip().startswith('#') and not re.match(r'^\.LBB', l)]
if len(sys.argv) > 3 and sys.argv[3] == 'kernels':
    # ga-core's own assembly: the AVX2 copies of the slice kernels.
    names = sorted(f for f in funcs if 'kernels' in f and ('avx2' in f or '3x86' in f))
else:
    names = sorted(f for f in funcs if re.match(r"^([bc]|g3|g4)_", f))
print(f"{'kernel':<16}" + ''.join(f"{c:>22}" for c in cpus) + "   uops")
for n in names:
    body = loop_body(funcs[n])
    if not body: print(n, 'no loop'); continue
    open(BODY,'w').write('\n'.join(body)+'\n')
    row = f"{n:<16}"
    for c in cpus:
        out = subprocess.run([MCA, f'-mcpu={c}', '-iterations=200', BODY], capture_output=True, text=True).stdout
        cyc = int(re.search(r'Total Cycles:\s+(\d+)', out).group(1)); rt = re.search(r'Block RThroughput:\s+([\d.]+)', out).group(1)
        uops = re.search(r'Total uOps:\s+(\d+)', out).group(1)
        row += f"{cyc/200:>10.1f} cyc (rt {rt:>4})"
    row += f"   {int(uops)//200}"
    print(row)
