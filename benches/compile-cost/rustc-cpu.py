#!/usr/bin/env python3
"""RUSTC_WRAPPER that appends `crate cpu_seconds wall_seconds` for each rustc run to the
file named by $RUSTC_CPU_LOG: CPU time (user + system) is far less disturbed than wall
time when other work shares the cores."""
import os
import resource
import subprocess
import sys
import time

args = sys.argv[1:]
start = time.time()
status = subprocess.call(args)
wall = time.time() - start
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
if "--crate-name" in args:
    name = args[args.index("--crate-name") + 1]
    with open(os.environ["RUSTC_CPU_LOG"], "a") as log:
        log.write(f"{name} {usage.ru_utime + usage.ru_stime:.2f} {wall:.2f}\n")
sys.exit(status)
