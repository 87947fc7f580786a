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
STORE = re.compile(r'\s+v?mov(ups|upd|aps|apd|ss|sd|d|q|lps|hps|lpd|hpd|dqu|dqa)\s+%[xyz]mm\d+,\s*-?\d*\(')
def store_bytes(body):
    """Bytes a loop body stores (vector moves to memory), to count its items."""
    size = {'ss': 4, 'd': 4, 'sd': 8, 'q': 8, 'lps': 8, 'hps': 8, 'lpd': 8, 'hpd': 8}
    total = 0
    for l in body:
        m = STORE.match(l)
        if m:
            reg = re.search(r'%([xyz])mm', l).group(1)
            total += size.get(m.group(1), {'x': 16, 'y': 32, 'z': 64}[reg])
    return total
print(f"{'kernel':<16}" + ''.join(f"{c:>22}" for c in cpus) + "   uops  items")
for n in names:
    # The rotor-product kernels take 8 or 16 (f32), 4 or 8 (f64) items a round. A one-item
    # loop LLVM unrolled or vectorised across items has a main loop and a one-item tail:
    # the main loop is what a batch runs, so it is measured, per item (its stores over the
    # tail's).
    tail = loop_body(funcs[n])
    body = loop_body(funcs[n], main_loop='rotor_product' in n)
    if not body: print(n, 'no loop'); continue
    items = 1
    # A batch loop, or a kernel whose loop LLVM vectorised across items (the per-item
    # sandwich in `sandwich_pairs`): the main loop, per item.
    if (n.startswith('b_') or (KERNELS and 'rotor_product' not in n)) and tail and store_bytes(tail):
        main = loop_body(funcs[n], main_loop=True)
        across = store_bytes(main) // store_bytes(tail)
        if main != tail and across in (2, 4, 8, 16) and store_bytes(main) == across * store_bytes(tail):
            body, items = main, across
    open(BODY,'w').write('\n'.join(body)+'\n')
    row = f"{n:<16}"
    for c in cpus:
        out = subprocess.run([MCA, f'-mcpu={c}', '-iterations=200', BODY], capture_output=True, text=True).stdout
        if 'Total Cycles' not in out:
            # llvm-mca 14 does not know every AVX-512 instruction.
            row += f"{'not modelled':>22}"; uops = '0'; continue
        cyc = int(re.search(r'Total Cycles:\s+(\d+)', out).group(1)); rt = re.search(r'Block RThroughput:\s+([\d.]+)', out).group(1)
        uops = re.search(r'Total uOps:\s+(\d+)', out).group(1)
        row += f"{cyc/200/items:>10.1f} cyc (rt {float(rt)/items:>4.1f})"
    row += f"   {int(uops)//200//items:>4}  {items}"
    print(row)
