#!/usr/bin/env python3
"""Runs Doxygen on the public headers and fails on any warning other than an
undocumented data member or enumerator: every public type and function must
have at least a one-line description, and every doc comment must parse.

Usage: docs_complete.py DOXYGEN DOXYFILE WARNINGS_LOG
"""
import os
import re
import subprocess
import sys

doxygen, doxyfile, log = sys.argv[1:4]
# Doxygen opens its warning log before it creates its output folder.
os.makedirs(os.path.dirname(log), exist_ok=True)
if os.path.exists(log):
    os.remove(log)
run = subprocess.run([doxygen, doxyfile], capture_output=True, text=True)
if run.returncode != 0:
    sys.exit(f"doxygen failed ({run.returncode}):\n{run.stderr}")
allowed = re.compile(r"is not documented\.$")
member = re.compile(r"\((variable|enumvalue)\)")
bad = [line for line in open(log).read().splitlines()
       if line.strip() and not (allowed.search(line) and member.search(line))]
if bad:
    print("\n".join(bad))
    sys.exit(f"{len(bad)} public items undocumented or doc comments broken")
print("docs complete")
