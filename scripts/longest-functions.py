#!/usr/bin/env python3
"""longest-functions.py: the longest functions of src/ and chapters/ (*.cpp,
*.hpp), longest first, as "lines  file:line  name" (issue 49's closing note:
the lines of the longest 10 functions, before and after a change).

    scripts/longest-functions.py [TREE [N]]      (TREE: a checkout, default .; N: rows, default 10)
    git archive REV src chapters | tar -x -C /tmp/rev && scripts/longest-functions.py /tmp/rev

A heuristic on this code's layout, not a C++ parser: a definition starts at
a line in column 0 (not a namespace, struct, class, enum, using, preprocessor
line, comment or closing brace) whose signature, over at most 9 lines, has
parentheses and ends in '{'; it ends at the next line that starts with '}'.
Counted: the signature's first line through that brace.  Member functions
defined inside a class body and lambdas count as part of what holds them."""
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else '.'
rows = int(sys.argv[2]) if len(sys.argv) > 2 else 10
skip = re.compile(r'^(namespace|struct|class|enum|union|extern|#|//|/\*|\*|}|using|typedef)')
found = []
for top in ('src', 'chapters'):
    for folder, _, files in os.walk(os.path.join(root, top)):
        for name in files:
            if not name.endswith(('.cpp', '.hpp')):
                continue
            path = os.path.join(folder, name)
            lines = open(path, errors='replace').read().split('\n')
            i = 0
            while i < len(lines):
                s = lines[i]
                if s and not s[0].isspace() and not skip.match(s) and '(' in s:
                    j, sig = i, s
                    while not sig.rstrip().endswith('{') and j + 1 < len(lines) and j - i < 8 and ';' not in lines[j]:
                        j += 1
                        sig += lines[j]
                    if sig.rstrip().endswith('{') and ')' in sig and not re.search(r'=\s*\{$|=\s*\[', sig):
                        k = j + 1
                        while k < len(lines) and not lines[k].startswith('}'):
                            k += 1
                        func = re.sub(r'\s*\(.*', '', s).split()[-1]
                        found.append((k - i + 1, os.path.relpath(path, root), i + 1, func))
                        i = k + 1
                        continue
                i += 1
found.sort(reverse=True)
for n, path, line, func in found[:rows]:
    print('%4d  %s:%d  %s' % (n, path, line, func))
