#!/usr/bin/env python3
"""The include arrows of the source tree point only downward.

Usage: check_rooms.py ROOT CORE_ROOMS RUNTIME_ROOMS  (room lists bottom to top, comma-separated, as
core/CMakeLists.txt and runtime/CMakeLists.txt declare them). It first checks itself on a small made-up
tree with known wrong arrows, so a checker that finds nothing cannot pass.

The libraries stack core < lang < stdlib < runtime. Inside core and runtime each folder is a room; a file
may include its own room and the rooms below it, never one above (core's own top-level files, such as
tolerance.hpp, sit below every core room). Every source folder must be a declared room with a README.md,
so a new folder cannot slip in beside the layering. Exit 1 listing each wrong arrow.
"""
import os
import re
import sys
import tempfile

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
LIBRARIES = ['core', 'lang', 'stdlib', 'runtime']


def check(root, core_rooms, runtime_rooms):
    """Every problem of the tree at `root`, one line each."""
    rooms = {'core': [''] + core_rooms, 'runtime': runtime_rooms}
    problems = []

    def place(path):
        """(library rank, room rank, room name) of a repository path, or None outside the libraries."""
        parts = path.split('/')
        if parts[0] not in LIBRARIES:
            return None
        lib = parts[0]
        if lib not in rooms:
            return (LIBRARIES.index(lib), 0, lib)
        folder = '/'.join(parts[1:-1])
        order = rooms[lib]
        if folder not in order:
            return (LIBRARIES.index(lib), -1, f'{lib}/{folder}')
        return (LIBRARIES.index(lib), order.index(folder), f'{lib}/{folder}'.rstrip('/'))

    for lib in rooms:
        for dirpath, dirnames, filenames in os.walk(os.path.join(root, lib)):
            rel = os.path.relpath(dirpath, root).replace(os.sep, '/')
            folder = '/'.join(rel.split('/')[1:])
            sources = [f for f in filenames if f.endswith(('.cpp', '.hpp'))]
            if sources and folder not in rooms[lib]:
                problems.append(f'{rel}/: a folder of sources that is no declared room of {lib} '
                                f'(add it to {lib}/CMakeLists.txt in its place, bottom to top)')
            if folder and folder in rooms[lib] and 'README.md' not in filenames:
                problems.append(f'{rel}/: a room without a README.md saying what it owns and may use')

    for lib in LIBRARIES:
        for dirpath, _, filenames in os.walk(os.path.join(root, lib)):
            for name in sorted(filenames):
                if not name.endswith(('.cpp', '.hpp')):
                    continue
                path = os.path.relpath(os.path.join(dirpath, name), root).replace(os.sep, '/')
                here = place(path)
                text = open(os.path.join(root, path), encoding='utf-8').read()
                for m in INCLUDE.finditer(text):
                    target = m.group(1)
                    there = place(target)
                    if there is None:
                        continue
                    line = text.count('\n', 0, m.start()) + 1
                    if not os.path.exists(os.path.join(root, target)):
                        problems.append(f'{path}:{line}: includes "{target}", which does not exist')
                    elif there[:2] > here[:2]:
                        problems.append(f'{path}:{line}: includes "{target}": {here[2]} may not use '
                                        f'{there[2]}, which is above it')
    return problems


def self_test():
    """The checker on a made-up tree: three wrong arrows, a stray folder, a room without a README."""
    files = {
        'core/tolerance.hpp': '',
        'core/geometry/README.md': '', 'core/geometry/v.hpp': '#include "core/tolerance.hpp"\n',
        'core/hlr/README.md': '', 'core/hlr/e.hpp': '#include "core/geometry/v.hpp"\n',
        'core/geometry/up.hpp': '#include "core/hlr/e.hpp"\n',
        'lang/p.hpp': '#include "runtime/base/x.hpp"\n',
        'runtime/base/README.md': '', 'runtime/base/x.hpp': '#include <vector>\n#include "core/hlr/e.hpp"\n',
        'runtime/cli/README.md': '', 'runtime/cli/y.hpp': '#include "runtime/base/x.hpp"\n',
        'runtime/base/z.cpp': '// text\n#include "runtime/cli/y.hpp"\n',
        'runtime/stray/s.cpp': '',
        'runtime/eval/e.cpp': '',
    }
    with tempfile.TemporaryDirectory() as root:
        for path, text in files.items():
            os.makedirs(os.path.dirname(os.path.join(root, path)), exist_ok=True)
            with open(os.path.join(root, path), 'w', encoding='utf-8') as f:
                f.write(text)
        found = sorted(p.split(':')[0] for p in check(root, ['geometry', 'hlr'], ['base', 'eval', 'cli']))
    expected = sorted(['core/geometry/up.hpp', 'lang/p.hpp', 'runtime/base/z.cpp', 'runtime/stray/',
                       'runtime/eval/'])
    found = [f.split(' ')[0] for f in found]
    if found != expected:
        print(f'the checker itself is wrong: on its made-up tree it found {found}, not {expected}')
        return False
    return True


def main():
    if not self_test():
        return 1
    root, core_rooms, runtime_rooms = sys.argv[1], sys.argv[2].split(','), sys.argv[3].split(',')
    problems = check(root, core_rooms, runtime_rooms)
    for p in problems:
        print(p)
    if problems:
        print(f'{len(problems)} problems; the order, bottom to top: {" < ".join(LIBRARIES)}; core: '
              f'{" < ".join(core_rooms)}; runtime: {" < ".join(runtime_rooms)}')
        return 1
    print('include arrows: all downward')
    return 0


if __name__ == '__main__':
    sys.exit(main())
