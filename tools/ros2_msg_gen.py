#!/usr/bin/env python3
"""Generates sanet's ROS 2 message layer from the .msg definitions under interfaces/ros2:
C++ structs with CDR encoders and decoders (messages.h, messages.cc), each type's schema text
(the definition followed by those of the types it uses, as ROS 2 tools expect) and its ROS 2
and DDS type names (the ROS 2 face's DDS types are these names over sanet's own CDR).

    ros2_msg_gen.py INTERFACES_DIR OUT_DIR
"""
import os
import re
import sys

PRIMITIVES = {  # .msg type: C++ type
    "bool": "bool",
    "byte": "std::uint8_t",
    "char": "std::uint8_t",
    "float32": "float",
    "float64": "double",
    "int8": "std::int8_t",
    "uint8": "std::uint8_t",
    "int16": "std::int16_t",
    "uint16": "std::uint16_t",
    "int32": "std::int32_t",
    "uint32": "std::uint32_t",
    "int64": "std::int64_t",
    "uint64": "std::uint64_t",
    "string": "std::string",
}
FIELD = re.compile(r"^(?P<type>[A-Za-z0-9_/]+)(?P<bound><=\d+)?(?P<array>\[(?P<size><=)?(?P<n>\d*)\])?\s+"
                   r"(?P<name>[a-z][a-z0-9_]*)(\s+(?P<default>.+))?$")
CONSTANT = re.compile(r"^(?P<type>[a-z0-9]+)\s+(?P<name>[A-Z][A-Z0-9_]*)\s*=\s*(?P<value>.+)$")


class Field:
    def __init__(self, m, package, where):
        self.name = m["name"]
        self.bound = int(m["bound"][2:]) if m["bound"] else None  # string<=N
        t = m["type"]
        if t in PRIMITIVES:
            self.base, self.message = t, None
        else:
            pkg, _, name = t.rpartition("/")
            self.base, self.message = None, (pkg or package, name)
        self.array = None  # None, ("fixed", n), ("bounded", n), ("unbounded", None)
        if m["array"]:
            if m["n"] and not m["size"]:
                self.array = ("fixed", int(m["n"]))
            elif m["n"]:
                self.array = ("bounded", int(m["n"]))
            else:
                self.array = ("unbounded", None)
        self.default = m["default"]
        if self.default and (not self.base or self.array or self.base == "string"):
            sys.exit(f"{where}: default values are supported for numbers only")


class Message:
    def __init__(self, package, name, path):
        self.package, self.name, self.path = package, name, path
        self.fields, self.constants = [], []
        with open(path) as f:
            self.text = f.read().strip() + "\n"
        for number, line in enumerate(self.text.splitlines(), 1):
            where = f"{path}:{number}"
            c = CONSTANT.match(line)
            if c:
                self.constants.append((c["type"], c["name"], c["value"].strip()))
                continue
            m = FIELD.match(line)
            if not m:
                sys.exit(f"{where}: not a field or a constant: {line!r}")
            self.fields.append(Field(m, package, where))

    @property
    def key(self):
        return (self.package, self.name)


def load(root):
    messages = {}
    for package in sorted(os.listdir(root)):
        folder = os.path.join(root, package, "msg")
        if not os.path.isdir(folder):
            continue
        for file in sorted(os.listdir(folder)):
            if file.endswith(".msg"):
                m = Message(package, file[:-4], os.path.join(folder, file))
                messages[m.key] = m
    for m in messages.values():
        for f in m.fields:
            if f.message and f.message not in messages:
                sys.exit(f"{m.path}: field {f.name} uses {'/'.join(f.message)}, which has no .msg here")
    return messages


def ordered(messages):
    """Every type after the types it uses."""
    done, order = set(), []

    def visit(key):
        if key in done:
            return
        done.add(key)
        for f in messages[key].fields:
            if f.message:
                visit(f.message)
        order.append(messages[key])

    for key in sorted(messages):
        visit(key)
    return order


def dependencies(messages, message):
    """The types `message` uses, each once, in order of first use (depth first)."""
    seen, order = set(), []

    def visit(m):
        for f in m.fields:
            if f.message and f.message not in seen:
                seen.add(f.message)
                order.append(messages[f.message])
                visit(messages[f.message])

    visit(message)
    return order


def schema(messages, message):
    parts = [message.text]
    for d in dependencies(messages, message):
        parts.append("=" * 80 + "\n" + f"MSG: {d.package}/{d.name}\n" + d.text)
    return "".join(parts)


PRIMITIVE_SIZES = {"bool": 1, "byte": 1, "char": 1, "int8": 1, "uint8": 1, "int16": 2, "uint16": 2, "float32": 4,
                   "int32": 4, "uint32": 4, "float64": 8, "int64": 8, "uint64": 8, "string": 5}


def least_size(messages, f, element=False):
    """The fewest bytes one value of the field (or one element of its array) takes in CDR."""
    one = PRIMITIVE_SIZES[f.base] if f.base else sum(least_size(messages, g) for g in messages[f.message].fields)
    if element or not f.array:
        return one
    return one * f.array[1] if f.array[0] == "fixed" else 4


def cpp_name(key):
    return f"{key[0]}::{key[1]}"


def cpp_type(f):
    base = PRIMITIVES[f.base] if f.base else cpp_name(f.message)
    if f.array and f.array[0] == "fixed":
        return f"std::array<{base}, {f.array[1]}>"
    if f.array:
        return f"std::vector<{base}>"
    return base


def cpp_literal(text):
    return "".join('"' + line.replace("\\", "\\\\").replace('"', '\\"') + '\\n"\n      ' for line in text.splitlines())


def header(order):
    out = ["// Generated by tools/ros2_msg_gen.py from interfaces/ros2: do not edit.",
           "#pragma once", "", "#include <array>", "#include <cstdint>", "#include <string>", "#include <vector>", "",
           '#include "ros2msg/cdr.h"', "", "namespace sanet::ros2msg {", ""]
    for m in order:
        out.append(f"namespace {m.package} {{")
        out.append(f"struct {m.name} {{")
        for t, name, value in m.constants:
            out.append(f"  static constexpr {PRIMITIVES[t]} {name} = {value};")
        for f in m.fields:
            out.append(f"  {cpp_type(f)} {f.name}{{{f.default or ''}}};")
        out.append("};")
        out.append(f"}}  // namespace {m.package}")
        out.append(f"void Write(CdrWriter& w, const {cpp_name(m.key)}& m);")
        out.append(f"bool Read(CdrReader& r, {cpp_name(m.key)}& m);")
        out.append(f"template <> struct TypeOf<{cpp_name(m.key)}> {{")
        out.append(f'  static constexpr const char* kName = "{m.package}/msg/{m.name}";')
        out.append(f'  static constexpr const char* kDdsName = "{m.package}::msg::dds_::{m.name}_";')
        out.append("  static const char* Definition();  // with the definitions of the types it uses")
        out.append("};")
        out.append("")
    out.append("}  // namespace sanet::ros2msg")
    return "\n".join(out) + "\n"


def read_call(f, target):
    label = f'"{f.owner}.{f.name}"'
    if f.base == "string":
        return f"r.GetString({target}, {f.bound or 0}, {label})"
    if f.base:
        return f"r.Get({target}, {label})"
    return f"Read(r, {target})"


def write_call(f, source):
    if f.base == "string":
        return f"w.PutString({source});"
    if f.base:
        return f"w.Put({source});"
    return f"Write(w, {source});"


def source(messages, order):
    out = ["// Generated by tools/ros2_msg_gen.py from interfaces/ros2: do not edit.",
           '#include "ros2msg/messages.h"', "", "namespace sanet::ros2msg {", ""]
    for m in order:
        for f in m.fields:
            f.owner = f"{m.package}/{m.name}"
        out.append(f"void Write(CdrWriter& w, const {cpp_name(m.key)}& m) {{")
        for f in m.fields:
            if f.array and f.array[0] == "fixed":
                out.append(f"  for (const auto& e : m.{f.name}) {write_call(f, 'e')}")
            elif f.array:
                out.append(f"  w.PutCount(m.{f.name}.size());")
                out.append(f"  for (const auto& e : m.{f.name}) {write_call(f, 'e')}")
            else:
                out.append(f"  {write_call(f, 'm.' + f.name)}")
        if not m.fields:
            out.append("  (void)w;")
            out.append("  (void)m;")
        out.append("}")
        out.append("")
        out.append(f"bool Read(CdrReader& r, {cpp_name(m.key)}& m) {{")
        for f in m.fields:
            label = f'"{f.owner}.{f.name}"'
            if f.array and f.array[0] == "fixed":
                out.append(f"  for (auto& e : m.{f.name})")
                out.append(f"    if (!{read_call(f, 'e')}) return false;")
            elif f.array:
                bound = f.array[1] or 0
                least = max(1, least_size(messages, f, element=True))
                out.append("  {")
                out.append("    std::uint32_t n = 0;")
                out.append(f"    if (!r.GetCount(n, {bound}, {least}, {label})) return false;")
                out.append(f"    m.{f.name}.resize(n);")
                out.append(f"    for (auto& e : m.{f.name})")
                out.append(f"      if (!{read_call(f, 'e')}) return false;")
                out.append("  }")
            else:
                out.append(f"  if (!{read_call(f, 'm.' + f.name)}) return false;")
        out.append("  return true;")
        out.append("}")
        out.append("")
        out.append(f"const char* TypeOf<{cpp_name(m.key)}>::Definition() {{")
        out.append(f"  return {cpp_literal(schema(messages, m)).rstrip()};")
        out.append("}")
        out.append("")
    out.append("}  // namespace sanet::ros2msg")
    return "\n".join(out) + "\n"


def write_if_changed(path, text):
    """Unchanged text keeps its file (and what was compiled from it); the time says it is current."""
    if os.path.exists(path):
        with open(path) as f:
            if f.read() == text:
                os.utime(path)
                return
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def main():
    root, out = sys.argv[1], sys.argv[2]
    messages = load(root)
    order = ordered(messages)
    os.makedirs(os.path.join(out, "ros2msg"), exist_ok=True)
    write_if_changed(os.path.join(out, "ros2msg", "messages.h"), header(order))
    write_if_changed(os.path.join(out, "ros2msg", "messages.cc"), source(messages, order))


if __name__ == "__main__":
    main()
