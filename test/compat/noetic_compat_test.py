#!/usr/bin/python3
"""The package's code runs on ROS Noetic (Ubuntu 20.04: Python 3.8, GCC 9).

Python: every Python file of the package (src/, scripts/, test/, bench/,
fuzz/, setup.py, cfg/*.cfg; a file counts when it ends in .py or starts with
a python shebang) parses with ast.parse(feature_version=(3, 8)), and its AST
uses none of the newer calls of PY_RULES: keyword arguments, methods,
module functions, imports and builtin generics at run time.

C++: no source or header under src/, include/, test/, bench/ or fuzz/ uses
a C++20 header, name or construct of CPP_RULES (comments and string
literals stripped first).

A failure lists every file:line with the construct and the version it needs.
"""
import ast
import os
import re
import sys
import unittest

import rosunit

PKG = 'rigid_body_sim'
ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..'))
PY_TARGET = (3, 8)
PY_DIRS = ('src', 'scripts', 'test', 'bench', 'fuzz', 'cfg')
PY_FILES = ('setup.py',)
CPP_DIRS = ('src', 'include', 'test', 'bench', 'fuzz')
CPP_SUFFIXES = ('.cpp', '.cc', '.h', '.hpp')

# keyword argument -> (callee names it is checked on, or None: any call; version)
PY_KEYWORDS = {
    'process_group': (None, '3.11'),               # subprocess.Popen/run/...
    'strict': (('zip',), '3.10'),
}
# method name -> version (called on any object)
PY_METHODS = {
    'removeprefix': '3.9', 'removesuffix': '3.9',  # str, bytes
    'bit_count': '3.10',                           # int
    'is_relative_to': '3.9',                       # pathlib
}
# module -> {name: version}, as module.name or `from module import name`
PY_MODULE_NAMES = {
    'functools': {'cache': '3.9'},
    'asyncio': {'to_thread': '3.9'},
    'random': {'randbytes': '3.9'},
    'math': {'lcm': '3.9', 'nextafter': '3.9', 'ulp': '3.9'},
    'itertools': {'pairwise': '3.10'},
    'os': {'waitstatus_to_exitcode': '3.9'},
}
PY_MODULES = {'zoneinfo': '3.9', 'graphlib': '3.9', 'tomllib': '3.11'}
# list[int] and the like, evaluated at run time (3.8 needs typing.List).
PY_GENERICS = {'list', 'dict', 'tuple', 'set', 'frozenset', 'type'}

CPP_RULES = [
    (re.compile(r'#\s*include\s*<(span|format|numbers|concepts|ranges|bit|compare|'
                r'source_location|coroutine|barrier|latch|semaphore|stop_token|'
                r'syncstream)>'), 'a C++20 header'),
    (re.compile(r'\bstd::(ssize|span|bit_cast|midpoint|lerp|erase_if|to_array|format|numbers|'
                r'is_constant_evaluated|remove_cvref|bind_front)\b'), 'a C++20 name'),
    (re.compile(r'\.(contains|starts_with|ends_with)\s*\('), 'a C++20 member function'),
    (re.compile(r'[{,(]\s*\.[A-Za-z_]\w*\s*=(?!=)'), 'a designated initialiser (C++20)'),
    (re.compile(r'<=>|\bconsteval\b|\bconstinit\b|\bco_(await|return|yield)\b'),
     'C++20 syntax'),
]


def python_files():
    paths = [os.path.join(ROOT, f) for f in PY_FILES]
    for top in PY_DIRS:
        for dirpath, dirnames, filenames in os.walk(os.path.join(ROOT, top)):
            dirnames[:] = sorted(d for d in dirnames if not d.startswith('.'))
            for f in sorted(filenames):
                path = os.path.join(dirpath, f)
                if f.endswith('.py') or is_python_script(path):
                    paths.append(path)
    return paths


def is_python_script(path):
    with open(path, 'rb') as f:
        first = f.readline(200)
    return first.startswith(b'#!') and b'python' in first


def cpp_files():
    for top in CPP_DIRS:
        for dirpath, dirnames, filenames in os.walk(os.path.join(ROOT, top)):
            dirnames[:] = sorted(d for d in dirnames if not d.startswith('.'))
            for f in sorted(filenames):
                if f.endswith(CPP_SUFFIXES):
                    yield os.path.join(dirpath, f)


def callee_name(func):
    if isinstance(func, ast.Name):
        return func.id
    if isinstance(func, ast.Attribute):
        return func.attr
    return None


def python_findings(source, filename):
    """[(line, what, version)] of the source's constructs newer than PY_TARGET."""
    try:
        tree = ast.parse(source, filename, feature_version=PY_TARGET)
    except SyntaxError as e:
        return [(e.lineno or 0, 'syntax: %s' % e.msg, '> %d.%d' % PY_TARGET)]
    aliases = {}   # local name -> module, from `import module [as name]`
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for a in node.names:
                aliases[a.asname or a.name] = a.name
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            for kw in node.keywords:
                if kw.arg in PY_KEYWORDS:
                    callees, version = PY_KEYWORDS[kw.arg]
                    name = callee_name(node.func)
                    if callees is None or name in callees:
                        found.append((node.lineno, '%s(%s=)' % (name, kw.arg), version))
            if isinstance(node.func, ast.Attribute) and node.func.attr in PY_METHODS:
                found.append((node.lineno, '.%s()' % node.func.attr,
                              PY_METHODS[node.func.attr]))
        elif isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
            module = aliases.get(node.value.id)
            version = PY_MODULE_NAMES.get(module, {}).get(node.attr)
            if version:
                found.append((node.lineno, '%s.%s' % (module, node.attr), version))
        elif isinstance(node, ast.ImportFrom):
            for a in node.names:
                version = PY_MODULE_NAMES.get(node.module, {}).get(a.name)
                if version:
                    found.append((node.lineno, 'from %s import %s' % (node.module, a.name),
                                  version))
            if (node.module or '').split('.')[0] in PY_MODULES:
                found.append((node.lineno, 'module %s' % node.module,
                              PY_MODULES[node.module.split('.')[0]]))
        elif isinstance(node, ast.Import):
            for a in node.names:
                if a.name.split('.')[0] in PY_MODULES:
                    found.append((node.lineno, 'module %s' % a.name,
                                  PY_MODULES[a.name.split('.')[0]]))
        elif (isinstance(node, ast.Subscript) and isinstance(node.value, ast.Name)
              and node.value.id in PY_GENERICS):
            found.append((node.lineno, '%s[...]' % node.value.id, '3.9'))
    return sorted(found)


def strip_cpp(text):
    """The text with comments and string/char literals blanked, lines kept."""
    pattern = re.compile(r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'',
                         re.S)
    return pattern.sub(lambda m: re.sub(r'[^\n]', ' ', m.group(0)), text)


def cpp_findings(text):
    """[(line, what)] of the C++ text's constructs newer than C++17."""
    stripped = strip_cpp(text)
    found = []
    for lineno, line in enumerate(stripped.split('\n'), 1):
        for pattern, what in CPP_RULES:
            m = pattern.search(line)
            if m:
                found.append((lineno, '%s: %s' % (what, m.group(0).strip())))
    return found


class NoeticCompat(unittest.TestCase):

    def test_python_files_run_on_python_3_8(self):
        files = python_files()
        self.assertTrue(any(f.endswith('setup.py') for f in files))
        self.assertTrue(any(f.endswith('.cfg') for f in files), 'cfg/*.cfg not found')
        problems = []
        for path in files:
            with open(path, encoding='utf-8') as f:
                source = f.read()
            for line, what, version in python_findings(source, path):
                problems.append('%s:%d: %s needs Python %s' % (os.path.relpath(path, ROOT), line,
                                                               what, version))
        self.assertEqual(problems, [], 'newer than Python %d.%d:\n' % PY_TARGET
                         + '\n'.join(problems))

    def test_cpp_sources_are_cpp17(self):
        problems = []
        for path in cpp_files():
            with open(path, encoding='utf-8', errors='replace') as f:
                for line, what in cpp_findings(f.read()):
                    problems.append('%s:%d: %s' % (os.path.relpath(path, ROOT), line, what))
        self.assertEqual(problems, [], 'newer than C++17 / GCC 9:\n' + '\n'.join(problems))

    def test_the_rules_catch_what_they_name(self):
        for snippet in ('subprocess.Popen(["ls"], process_group=0)',
                        'subprocess.run(["ls"], process_group=0)',
                        'list(zip(a, b, strict=True))',
                        '"ab".removeprefix("a")',
                        'n.bit_count()',
                        'import functools\n@functools.cache\ndef f(): pass',
                        'from functools import cache',
                        'import random as r\nr.randbytes(4)',
                        'import asyncio\nasyncio.to_thread(f)',
                        'x: list[int] = []',
                        'import tomllib',
                        'match x:\n    case 1: pass'):
            self.assertTrue(python_findings(snippet, '<snippet>'), snippet)
        for snippet in ('subprocess.Popen(["ls"], start_new_session=True)', 'zip(a, b)',
                        'from typing import List\nx: List[int] = []', 'd["list"]',
                        'import math\nmath.dist(a, b)'):
            self.assertEqual(python_findings(snippet, '<snippet>'), [], snippet)
        for snippet in ('#include <span>', 'auto n = std::ssize(v);', 'if (m.contains(k)) {}',
                        'Point p{.x = 1, .y = 2};', 'auto c = a <=> b;'):
            self.assertTrue(cpp_findings(snippet), snippet)
        for snippet in ('// std::span in a comment', 'f(".x = 1");', 'if (a.x == 1) {}',
                        'Point p{1, 2};', 'auto q = m.find(k);'):
            self.assertEqual(cpp_findings(snippet), [], snippet)


if __name__ == '__main__':
    rosunit.unitrun(PKG, 'noetic_compat', NoeticCompat, sys.argv)
