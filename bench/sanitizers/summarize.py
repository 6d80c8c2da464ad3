#!/usr/bin/env python3
"""Collects the sanitizer reports of one bench/sanitizers/run.sh run.

Reads the outputs the ctest suite left in <build>/tests/ (files output,
failing_output, stdout of every test directory) and the console logs of
the stability suite (<build>/stability/<group>/<case>/stdout.txt), finds
every AddressSanitizer, UndefinedBehaviorSanitizer ("runtime error:") and
LeakSanitizer report, and writes them grouped by kind and place: one entry
per distinct report with where it occurred, the top of its stack and the
first frame in our own code (source/, include/, tests/ of the repository).
Also lists the ctest failures and the leak suppressions that were used.
Exit status 1 if any report was found, else 0.
"""
import argparse
import collections
import os
import re
import sys

FRAME = re.compile(r'^\s*#(\d+) 0x[0-9a-f]+(?: in (.*?))? (\(?[^ ]+?\)?)$')
ASAN = re.compile(r'==\d+==ERROR: AddressSanitizer: (\S+)(.*)')
LSAN = re.compile(r'==\d+==ERROR: LeakSanitizer: detected memory leaks')
LEAK = re.compile(r'^(Direct|Indirect) leak of (\d+) byte\(s\) in (\d+) object\(s\) allocated from:')
UBSAN = re.compile(r'(\S+?):(\d+):(\d+): runtime error: (.*)$')
SUPP_LINE = re.compile(r'^\s*(\d+)\s+(\d+)\s+(\S+)\s*$')


def parse_frames(lines, i, lookahead=8):
    """The stack that starts at lines[i] or within the next few lines."""
    frames = []
    for k in range(i, min(i + lookahead, len(lines))):
        if FRAME.match(lines[k]):
            i = k
            break
    while i < len(lines):
        m = FRAME.match(lines[i])
        if not m:
            break
        frames.append((m.group(2) or '?', m.group(3).strip('()')))
        i += 1
    return frames, i


class Collector:
    def __init__(self, repo):
        self.ours = [os.path.join(repo, d) + '/' for d in ('source', 'include', 'tests')]
        self.repo = repo
        self.reports = collections.OrderedDict()  # key -> dict
        self.suppressions = collections.Counter()  # template -> [count]
        self.suppressed_bytes = collections.Counter()
        self.files_with_reports = set()

    def our_frame(self, frames):
        for func, loc in frames:
            if any(loc.startswith(p) for p in self.ours):
                return func, self.short(loc)
        return None

    def short(self, loc):
        return loc[len(self.repo) + 1:] if loc.startswith(self.repo + '/') else loc

    def top_frame(self, frames):
        """First frame that is not the sanitizer run-time or the allocator."""
        for func, loc in frames:
            if 'libasan' in loc or 'libubsan' in loc or re.match(
                    r'(operator new|operator delete|malloc|calloc|realloc|free|'
                    r'posix_memalign|aligned_alloc|strdup|__interceptor_)', func):
                continue
            return func, self.short(loc)
        return frames[0] if frames else ('?', '?')

    def add(self, kind, detail, frames, where, extra=''):
        ours = self.our_frame(frames)
        top = self.top_frame(frames)
        anchor = ours if ours else top
        key = (kind, detail if kind.startswith('UBSan') else '', anchor[1])
        r = self.reports.get(key)
        if r is None:
            r = self.reports[key] = dict(kind=kind, detail=detail, ours=ours, top=top,
                                         frames=frames, where=collections.Counter(),
                                         count=0, extra=extra)
        r['count'] += 1
        r['where'][where] += 1
        self.files_with_reports.add(where)

    def scan(self, path, where):
        try:
            with open(path, errors='replace') as f:
                lines = f.read().splitlines()
        except OSError:
            return
        i = 0
        in_supp = False
        while i < len(lines):
            line = lines[i]
            m = ASAN.search(line)
            if m:
                kind = 'ASan ' + m.group(1)
                # the access line (READ/WRITE of size ...) follows the header
                access = lines[i + 1].strip() if i + 1 < len(lines) else ''
                if not access.startswith(('READ', 'WRITE')):
                    access = ''
                frames, j = parse_frames(lines, i + 1)
                self.add(kind, access.split(' at ')[0], frames, where)
                i = max(j, i + 1)
                continue
            m = UBSAN.search(line)
            if m:
                frames, j = parse_frames(lines, i + 1)
                loc = '%s:%s' % (m.group(1), m.group(2))
                if not frames:
                    frames = [('?', loc)]
                self.add('UBSan', m.group(4), [('(report)', loc)] + frames, where)
                i = max(j, i + 1)
                continue
            if LSAN.search(line):
                i += 1
                continue
            m = LEAK.match(line)
            if m:
                frames, j = parse_frames(lines, i + 1)
                self.add('LSan %s leak' % m.group(1).lower(), '', frames, where,
                         extra='%s bytes in %s objects' % (m.group(2), m.group(3)))
                i = max(j, i + 1)
                continue
            if line.startswith('Suppressions used:'):
                in_supp = True
            elif in_supp:
                s = SUPP_LINE.match(line)
                if s:
                    self.suppressions[s.group(3)] += int(s.group(1))
                    self.suppressed_bytes[s.group(3)] += int(s.group(2))
                elif line.strip() and not line.strip().startswith(('count', '---')):
                    in_supp = False
            i += 1


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--repo', required=True)
    ap.add_argument('--build', required=True)
    ap.add_argument('--out', required=True)
    args = ap.parse_args()
    repo = os.path.realpath(args.repo)
    build = os.path.realpath(args.build)
    c = Collector(repo)

    n_test_dirs = 0
    tests_root = os.path.join(build, 'tests')
    for root, _dirs, files in sorted(os.walk(tests_root)):
        names = [f for f in ('output', 'failing_output', 'stdout') if f in files]
        if not names:
            continue
        n_test_dirs += 1
        where = 'ctest ' + os.path.relpath(root, tests_root)
        for f in names:
            c.scan(os.path.join(root, f), where)
    n_cases = 0
    stab_root = os.path.join(build, 'stability')
    for root, _dirs, files in sorted(os.walk(stab_root)):
        if 'stdout.txt' in files:
            n_cases += 1
            c.scan(os.path.join(root, 'stdout.txt'),
                   'stability ' + os.path.relpath(root, stab_root))

    out = []
    out.append('Sanitizer summary for %s' % build)
    out.append('scanned: %d ctest output directories, %d stability cases' % (n_test_dirs, n_cases))
    total = sum(r['count'] for r in c.reports.values())
    out.append('sanitizer reports: %d (%d distinct) in %d runs' %
               (total, len(c.reports), len(c.files_with_reports)))
    out.append('')
    for n, r in enumerate(c.reports.values(), 1):
        out.append('[%d] %s%s  (%d report(s))' % (n, r['kind'],
                                                  (': ' + r['detail']) if r['detail'] else '',
                                                  r['count']))
        if r['extra']:
            out.append('    first: %s' % r['extra'])
        out.append('    top of stack : %s  %s' % r['top'])
        out.append('    first in ours: %s' % ('%s  %s' % r['ours'] if r['ours'] else
                                              '(none: no frame in source/, include/ or tests/)'))
        runs = sorted(r['where'])
        out.append('    in %d run(s): %s%s' % (len(runs), ', '.join(runs[:8]),
                                               ' ...' if len(runs) > 8 else ''))
        out.append('    stack (first occurrence):')
        for k, (func, loc) in enumerate(r['frames'][:20]):
            out.append('      #%-2d %s  %s' % (k, func[:110], c.short(loc)))
        out.append('')
    if c.suppressions:
        out.append('Leak suppressions used (summed over all runs): count, bytes, pattern')
        for t, n in c.suppressions.most_common():
            out.append('  %6d %10d  %s' % (n, c.suppressed_bytes[t], t))
        out.append('')

    sample = os.path.join(build, 'logs', 'lsan-suppressions.txt')
    if os.path.exists(sample):
        out.append('What lsan.supp hides (logs/lsan-suppressions.txt; count, bytes, pattern):')
        with open(sample, errors='replace') as f:
            out.extend('  ' + l.rstrip() for l in f
                       if l.strip() and not l.startswith('---'))
        out.append('')

    ctest_log = os.path.join(build, 'logs', 'ctest.log')
    if os.path.exists(ctest_log):
        with open(ctest_log, errors='replace') as f:
            text = f.read()
        failed = re.findall(r'^\s*\d+ - (\S+) \((\w+)\)', text, re.M)
        m = re.search(r'^.*tests passed.*$', text, re.M)
        out.append('ctest: %s' % (m.group(0).strip() if m else 'no result line'))
        for name, why in failed:
            stage = 'DIFF' if re.search(re.escape(name) + r': DIFF failed', text) else \
                    'RUN' if re.search(re.escape(name) + r': RUN failed', text) else \
                    'BUILD' if re.search(re.escape(name) + r': BUILD failed', text) else why
            out.append('  failed: %s (%s stage)' % (name, stage))
        out.append('')

    text = '\n'.join(out) + '\n'
    with open(args.out, 'w') as f:
        f.write(text)
    sys.stdout.write(text)
    return 1 if c.reports else 0


if __name__ == '__main__':
    sys.exit(main())
