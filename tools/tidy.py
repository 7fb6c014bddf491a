#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""clang-tidy over every C++ source of TolTurn; a file whose exact input passed before is not
checked again.

What clang-tidy finds in a file is a function of what it reads and how it runs. For every source
the hash covers: the raw text of the source and of every header it reads (so directives, macros
and NOLINT comments count), the preprocessed translation unit as clang-tidy parses it (with
__clang_analyzer__ defined; line markers kept, with each header's path and system-header flag,
and whether the header filter lets clang-tidy report in it), the compile command, the .clang-tidy
files above it, the clang-tidy binary and its LLVM libraries, this script, and the options it
passes. A file whose input cannot all be read (or when clang++ or ldd is missing) gets no hash and
is always checked. tools/tidy-passed.txt records the hash, with the file's path, of every file that
passed; a file whose hash is recorded is skipped. The hash is taken again after a file passes and
recorded only if nothing changed meanwhile. The source and build folders (each under its real path
and as CMake spells it, which differ in a checkout reached through a symlink) are replaced by
placeholders, so a record made in one checkout holds in another.

usage: tools/tidy.py BUILD_DIR [FILE...]   every source, or only the FILEs given;
                                          TOLTURN_TIDY_ALL=1 checks even those recorded
"""
import codecs
import concurrent.futures
import fcntl
import hashlib
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

LOGICAL_SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), '..'))
SOURCE_DIR = os.path.realpath(LOGICAL_SOURCE_DIR)
RECORD = os.path.join(SOURCE_DIR, 'tools', 'tidy-passed.txt')
# The heaviest translation units (tests and widgets, which include the whole GUI) first and the
# light core ones last, one file per process, so that neither core idles at the end.
FOLDERS = ['tests', 'widgets', 'app', 'benchmarks', 'resources', 'translations', 'core']
JOBS = 2
ENTRIES_PER_FILE = 6  # hashes kept per file: the dev and ci builds' flags, and earlier ones
COMPILERS = ('c++', 'g++', 'gcc', 'cc', 'clang', 'clang++')  # whose commands clang-tidy reads as we hash them
LINE_MARKER = re.compile(rb'^# \d+ "((?:[^"\\]|\\.)*)"', re.MULTILINE)


def sources():
    found = []
    for folder in FOLDERS:
        paths = []
        for root, _, files in os.walk(os.path.join(SOURCE_DIR, folder)):
            paths += [os.path.join(root, f) for f in files if f.endswith('.cpp')]
        found += sorted(paths)
    return found


class Hasher:
    def __init__(self, folders, tidy_binary, options, checked_headers):
        self.folders = folders  # (spelling, placeholder), longest spelling first
        self.checked_headers = checked_headers  # the header filter clang-tidy gets, compiled
        self.clang = os.path.join(os.path.dirname(tidy_binary), 'clang++')  # the preprocessor of clang-tidy's LLVM
        self.options = options
        self.raw = {}  # path -> hash of the file's bytes, for this run
        self.fixed = self.tool_identity(tidy_binary)

    def neutral(self, text):
        """`text` with every spelling of the build and source folders replaced by a placeholder."""
        for spelling, placeholder in self.folders:
            text = text.replace(spelling, placeholder)
        return text

    def tool_identity(self, tidy_binary):
        """The hash of clang-tidy, its libraries, its preprocessor, this script and the options; None,
        with a message, when one of them cannot be found (then nothing is skipped or recorded)."""
        if not os.path.exists(self.clang):
            print(f'tidy: {self.clang} (the preprocessor of this clang-tidy) is missing: '
                  'every file is checked and none recorded', file=sys.stderr)
            return None
        try:
            run = subprocess.run(['ldd', tidy_binary], capture_output=True, text=True, check=False)
        except OSError as error:
            run = subprocess.CompletedProcess([], 1, '', str(error))
        if run.returncode != 0 and 'not a dynamic executable' not in run.stdout + run.stderr:  # static: none
            print(f'tidy: the libraries of {tidy_binary} are unknown ({run.stderr.strip()}): '
                  'every file is checked and none recorded', file=sys.stderr)
            return None
        libraries = run.stdout if run.returncode == 0 else ''
        digest = hashlib.sha256()
        for path in [tidy_binary, os.path.realpath(__file__), os.path.realpath(self.clang)] + sorted(
                re.findall(r'=> (\S*(?:clang|LLVM)\S*) ', libraries)):
            content = self.file_hash(path)
            if content is None:
                return None
            digest.update(content.encode())
        digest.update(' '.join(self.options).encode())
        return digest.digest()

    def file_hash(self, path):
        if path not in self.raw:
            try:
                with open(path, 'rb') as f:
                    self.raw[path] = hashlib.sha256(f.read()).hexdigest()
            except OSError:
                self.raw[path] = None  # its hash is unknown: the file that reads it is checked
        return self.raw[path]

    def configurations(self, path):
        """Every .clang-tidy from the file's folder up to the source folder (clang-tidy uses the nearest)."""
        found, folder = [], os.path.dirname(path)
        while folder.startswith(SOURCE_DIR):
            candidate = os.path.join(folder, '.clang-tidy')
            if os.path.exists(candidate):
                found.append(candidate)
            if folder == SOURCE_DIR:
                break
            folder = os.path.dirname(folder)
        return found

    def input_hash(self, path, entries):
        """The hash of everything clang-tidy reads for `path`, or None (then it is always checked)."""
        if self.fixed is None:
            return None
        digest = hashlib.sha256(self.fixed)
        digest.update(self.neutral(os.path.relpath(path, SOURCE_DIR)).encode())
        for entry in entries:
            args = entry['arguments'] if 'arguments' in entry else shlex.split(entry['command'])
            if os.path.basename(args[0]).split('-')[0] not in COMPILERS and os.path.basename(args[0]) not in COMPILERS:
                return None  # a compiler whose driver we do not mirror
            flags = preprocessor_flags(args[1:], entry['file'])
            digest.update(self.neutral(json.dumps([args[0], entry['directory'], flags])).encode())
            run = subprocess.run([self.clang, *flags, '-D__clang_analyzer__', '-E', '-C', '-w', path, '-o', '-'],
                                 cwd=entry['directory'], capture_output=True, check=False)
            if run.returncode != 0 or not run.stdout:
                return None  # clang-tidy will say why
            digest.update(self.neutral(run.stdout.decode('utf-8', 'surrogateescape')).encode('utf-8', 'surrogateescape'))
            headers = set()
            for marker in set(LINE_MARKER.findall(run.stdout)):
                # The name as written in the marker, with its C escapes (\\, \", octal) undone.
                name = codecs.escape_decode(marker)[0].decode('utf-8', 'surrogateescape')
                if not name.startswith('<'):  # not <built-in> or <command line>
                    full = os.path.normpath(os.path.join(entry['directory'], name))
                    content = self.file_hash(full)
                    if content is None:
                        return None
                    # Whether clang-tidy reports in it: the placeholders hide where a build folder lies.
                    reported = 'reported' if self.checked_headers.search(full) else 'silent'
                    headers.add(f'{self.neutral(full)} {content} {reported}\n')
            for header in sorted(headers):  # in the order of their neutral paths, the same in every checkout
                digest.update(header.encode('utf-8', 'surrogateescape'))
        for configuration in self.configurations(path):
            content = self.file_hash(configuration)
            if content is None:
                return None
            digest.update(f'{self.neutral(configuration)} {content}\n'.encode())
        return digest.hexdigest()


def preprocessor_flags(args, source):
    """The compile flags less the output, dependency-file and source arguments."""
    kept, skip = [], False
    for arg in args:
        if skip:
            skip = False
        elif arg in ('-o', '-MF', '-MT', '-MQ'):
            skip = True
        elif (arg == '-c' or arg == source or arg.startswith(('-o', '-M', '-Wp,-M', '--output'))):
            continue
        else:
            kept.append(arg)
    return kept


def read_record():
    record = {}
    try:
        with open(RECORD, encoding='utf-8') as f:
            for line in f:
                parts = line.split()
                if len(parts) == 2 and re.fullmatch('[0-9a-f]{64}', parts[0]):  # not a comment or merge mark
                    record.setdefault(parts[1], []).append(parts[0])
    except FileNotFoundError:
        pass
    return record


def write_record(passed, present):
    """Adds the hashes of the files that passed to the record, under a lock, merged with what is there."""
    header = ['# Hashes of the exact input of every file tools/tidy.py found clean (see there); written by\n',
              '# every tidy run. Commit it with the change: CI then checks only what changed.\n']
    try:
        with open(os.path.join(SOURCE_DIR, 'tools', '.tidy-passed.lock'), 'w', encoding='utf-8') as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            record = read_record()
            for relative, digest in passed.items():
                record[relative] = [d for d in record.get(relative, []) if d != digest] + [digest]
            lines = header + [f'{digest}  {relative}\n' for relative in sorted(record) if relative in present
                              for digest in record[relative][-ENTRIES_PER_FILE:]]
            handle, temporary = tempfile.mkstemp(dir=os.path.dirname(RECORD), prefix='.tidy-passed.')
            try:
                with os.fdopen(handle, 'w', encoding='utf-8') as f:
                    f.writelines(lines)
                os.chmod(temporary, 0o644)
                os.replace(temporary, RECORD)
            except BaseException:
                os.unlink(temporary)
                raise
    except OSError as error:
        print(f'tidy: the record of passed files was not written: {error}', file=sys.stderr)


def cmake_cache_value(build_dir, name):
    """A value from the build's CMakeCache.txt, or None."""
    try:
        with open(os.path.join(build_dir, 'CMakeCache.txt'), encoding='utf-8') as f:
            match = re.search(rf'^{name}:[A-Z]+=(.*)$', f.read(), re.MULTILINE)
    except OSError:
        return None
    return match.group(1) if match else None


def spellings(*paths):
    """The distinct absolute spellings of a folder, None and empty ones left out."""
    return {os.path.normpath(p) for p in paths if p}


def header_filter(source_spellings):
    """.clang-tidy's HeaderFilterRegex, as (the regex clang-tidy gets, its neutral form for the hash).
    The regex is anchored at this source folder under every spelling clang-tidy may see (the real
    path and CMake's), so that neither a checkout's own path (which may hold 'app/' or 'tests/')
    nor a symlink decides whose headers are checked."""
    with open(os.path.join(SOURCE_DIR, '.clang-tidy'), encoding='utf-8') as f:
        match = re.search(r"^HeaderFilterRegex:\s*'([^']*)'", f.read(), re.MULTILINE)
    below = '/(' + (match.group(1) if match else '.*') + ')'  # grouped: a '|' in it stays anchored
    anchors = '|'.join(re.sub(r'([.[\]{}()\\*+?^$|])', r'\\\1', s) for s in sorted(source_spellings))
    return f'^({anchors}){below}', '^@SOURCE@' + below  # llvm::Regex is POSIX ERE: no (?:...)


def main():
    if len(sys.argv) < 2:
        sys.exit('usage: tools/tidy.py BUILD_DIR [FILE...]')
    build_dir = os.path.realpath(sys.argv[1])
    with open(os.path.join(build_dir, 'compile_commands.json'), encoding='utf-8') as f:
        commands = {}
        for entry in json.load(f):
            commands.setdefault(os.path.realpath(os.path.join(entry['directory'], entry['file'])), []).append(entry)
    files = [os.path.realpath(p) for p in sys.argv[2:]] or sources()
    missing = [p for p in files if p not in commands]
    if missing:
        sys.exit('tidy: no compile command for ' + ', '.join(os.path.relpath(p, SOURCE_DIR) for p in missing))

    tidy_binary = os.path.realpath(shutil.which('clang-tidy') or sys.exit('tidy: clang-tidy is not installed'))
    source_spellings = spellings(SOURCE_DIR, LOGICAL_SOURCE_DIR, cmake_cache_value(build_dir, 'CMAKE_HOME_DIRECTORY'))
    build_spellings = spellings(build_dir, os.path.abspath(sys.argv[1]),
                                cmake_cache_value(build_dir, 'CMAKE_CACHEFILE_DIR'))
    folders = sorted([(s, '@BUILD@') for s in build_spellings] + [(s, '@SOURCE@') for s in source_spellings],
                     key=lambda pair: -len(pair[0]))  # the longest first: a build folder inside the source
    tidy_filter, neutral_filter = header_filter(source_spellings)
    options = ['--quiet', '--extra-arg=-Wno-everything', '--header-filter=' + tidy_filter]
    # Python's re and POSIX ERE accept the same paths for this pattern (no back-references).
    hasher = Hasher(folders, tidy_binary, options[:-1] + ['--header-filter=' + neutral_filter],
                    re.compile(tidy_filter))
    with concurrent.futures.ThreadPoolExecutor(JOBS) as pool:
        hashes = dict(zip(files, pool.map(lambda p: hasher.input_hash(p, commands[p]), files)))

    record = read_record()
    check_all = os.environ.get('TOLTURN_TIDY_ALL') == '1'
    relative = {p: os.path.relpath(p, SOURCE_DIR) for p in files}
    to_check = [p for p in files if check_all or hashes[p] is None or hashes[p] not in record.get(relative[p], [])]
    print(f'tidy: {len(files) - len(to_check)} of {len(files)} files unchanged since they passed; '
          f'checking {len(to_check)}', flush=True)

    def check(path):
        run = subprocess.run([tidy_binary, '-p', build_dir, *options, path], capture_output=True, text=True,
                             check=False)
        return run.returncode == 0, run.stdout + run.stderr

    failed, passed = [], {}
    with concurrent.futures.ThreadPoolExecutor(JOBS) as pool:
        for path, (ok, output) in zip(to_check, pool.map(check, to_check)):
            if not ok:
                failed.append(relative[path])
                print(output, end='', flush=True)
            elif hashes[path] is not None:
                passed[path] = hashes[path]

    # Recorded only if the input is still what was hashed: nothing edited or regenerated meanwhile.
    hasher.raw.clear()
    with concurrent.futures.ThreadPoolExecutor(JOBS) as pool:
        still = dict(zip(passed, pool.map(lambda p: hasher.input_hash(p, commands[p]), passed)))
    write_record({relative[p]: d for p, d in passed.items() if still[p] == d},
                 {os.path.relpath(p, SOURCE_DIR) for p in sources()})
    if failed:
        sys.exit('tidy: findings in ' + ', '.join(failed))
    print('tidy: no findings')


if __name__ == '__main__':
    main()
