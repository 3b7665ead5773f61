"""Turn AutoBenchmark's UART output into rows of ops.csv.

The target sends, per operation, a line "B <type> <op>", one line
"S <hex> <hex> ..." per operand set (operands, then results, as the bits of
the type), and "C <type> <op> <cycles> <inlined cycles> <samples>".
Here every result is compared with a double-precision (or exact rational)
reference computed from the very operands the target used.

Errors are absolute, in the units of the value (not raw counts). Results
whose exact value lies outside the type's range (sums and products that
overflow: wrapped for the integers and the seed, saturated for the library)
are left out of the error figures and counted in `out_of_range`. float gets
the Q16.16 operands, and its errors are taken over results inside the Q16.16
range too, the range the engine works in, so the columns compare like for
like (an absolute error of a float product near 1e9 says nothing useful).
"""
import math
from fractions import Fraction
import struct

# type name -> (kind, bits, fraction bits)
TYPES = {
    "int16": ("int", 16, 0),
    "int32": ("int", 32, 0),
    "int64": ("int", 64, 0),
    "Q8.8": ("fixed", 16, 8),
    "Q16.16": ("fixed", 32, 16),
    "Q24.8": ("fixed", 32, 8),
    "float": ("float", 32, None),
    "seed_Q16.16": ("fixed", 32, 16),
}

TYPE_ORDER = list(TYPES)
OP_ORDER = ["add", "sub", "mul", "div", "sqrt", "atan2", "sin", "cos",
            "sin_turns", "cos_turns", "mag2", "norm2", "mag3", "norm3"]

COLUMNS = ["type", "op", "cycles", "max_abs_err", "rms_err",
           "inline_cycles", "samples", "out_of_range"]

def decode(type_name, text):
    """The exact value (a Fraction) of one hex field sent for type_name."""
    kind, _, frac = TYPES[type_name]
    raw = int(text, 16)
    width = 4 * len(text)
    if kind == "float":
        return Fraction(struct.unpack(">f", raw.to_bytes(4, "big"))[0])
    if raw >= 1 << (width - 1):
        raw -= 1 << width
    return Fraction(raw, 1 << frac)


def value_range(type_name):
    kind, bits, frac = TYPES[type_name]
    if kind == "float":
        return value_range("Q16.16")
    return (Fraction(-(1 << (bits - 1)), 1 << frac),
            Fraction((1 << (bits - 1)) - 1, 1 << frac))


def angle_error(result, reference):
    """|result - reference| for angles, taken around the circle."""
    d = math.fmod(float(result) - reference, 2.0 * math.pi)
    return min(abs(d), 2.0 * math.pi - abs(d))


def sample_errors(type_name, op, fields):
    """Errors of one operand set: a list of floats, or None if the exact
    result is outside the type's range."""
    lo, hi = value_range(type_name)
    if op in ("sin_turns", "cos_turns"):
        turns = int(fields[0], 16) / 65536.0
        r = decode(type_name, fields[1])
        f = math.sin if op == "sin_turns" else math.cos
        return [abs(float(r) - f(2.0 * math.pi * turns))]
    values = [decode(type_name, f) for f in fields]
    if op in ("add", "sub", "mul", "div"):
        a, b, r = values
        exact = {"add": lambda: a + b, "sub": lambda: a - b,
                 "mul": lambda: a * b, "div": lambda: a / b}[op]()
        if exact < lo or exact > hi:
            return None
        return [float(abs(r - exact))]
    if op == "sqrt":
        a, r = values
        return [abs(float(r) - math.sqrt(float(a)))]
    if op == "atan2":
        y, x, r = values
        return [angle_error(r, math.atan2(float(y), float(x)))]
    if op in ("sin", "cos"):
        a, r = values
        f = math.sin if op == "sin" else math.cos
        return [abs(float(r) - f(float(a)))]
    if op in ("mag2", "mag3", "norm2", "norm3"):
        n = int(op[-1])
        comps, results = values[:n], values[n:]
        square = sum(c * c for c in comps)
        if square > hi:
            return None
        length = math.sqrt(float(square))
        if op.startswith("mag"):
            return [abs(float(results[0]) - length)]
        return [abs(float(r) - float(c) / length) for r, c in zip(results, comps)]
    raise ValueError("unknown operation %r" % op)


def parse(lines):
    """Rows (dicts with COLUMNS) from the UART lines of one or more runs."""
    rows = []
    current = None
    errors = []
    out_of_range = 0
    for line in lines:
        line = line.strip()
        if line.startswith("B "):
            _, type_name, op = line.split()
            if type_name not in TYPES:
                raise ValueError("unknown type %r" % type_name)
            current = (type_name, op)
            errors, out_of_range = [], 0
        elif line.startswith("S ") and current:
            e = sample_errors(current[0], current[1], line.split()[1:])
            if e is None:
                out_of_range += 1
            else:
                errors.extend(e)
        elif line.startswith("C "):
            _, type_name, op, cycles, inlined, samples = line.split()
            if current != (type_name, op):
                raise ValueError("C line without its B line: %r" % line)
            row = {"type": type_name, "op": op, "cycles": cycles,
                   "inline_cycles": inlined, "samples": samples,
                   "out_of_range": str(out_of_range)}
            if errors:
                row["max_abs_err"] = "%.3g" % max(errors)
                row["rms_err"] = "%.3g" % math.sqrt(
                    sum(e * e for e in errors) / len(errors))
            else:
                row["max_abs_err"] = row["rms_err"] = "NA"
            rows.append(row)
            current = None
    return rows


def sort_rows(rows):
    def key(row):
        t = TYPE_ORDER.index(row["type"]) if row["type"] in TYPE_ORDER else 99
        o = OP_ORDER.index(row["op"]) if row["op"] in OP_ORDER else 99
        return (t, o)
    return sorted(rows, key=key)
