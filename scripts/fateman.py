#!/usr/bin/env python3
"""Fateman's benchmark p*(p+1), p = (1+x+y+z+t)^N, in python-flint and SymPy's ring().

A measuring tool beside `cargo run --release --example fateman -- N`, not a dependency.
Usage: scripts/fateman.py N [--sympy M] [--repeat R] [--threads T]. Prints the term count
and, per engine, the median seconds of the product alone (the power is not timed); FLINT
runs on T threads (1 unless given, its default).
"""
import statistics
import sys
import time


def median_time(f, repeat):
    times, out = [], None
    for _ in range(repeat):
        t = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t)
    return statistics.median(times), out


def flint_product(n, repeat, threads):
    import flint
    flint.ctx.threads = threads
    ctx = flint.fmpz_mpoly_ctx.get(("x", "y", "z", "t"), "degrevlex")
    x, y, z, t = ctx.gens()
    p = (1 + x + y + z + t) ** n
    q = p + 1
    secs, prod = median_time(lambda: p * q, repeat)
    return secs, len(p), len(prod)


def sympy_product(n, repeat):
    from sympy import ZZ, ring
    _, x, y, z, t = ring("x,y,z,t", ZZ)
    p = (1 + x + y + z + t) ** n
    q = p + 1
    secs, prod = median_time(lambda: p * q, repeat)
    return secs, len(p), len(prod)


def main():
    args = sys.argv[1:]
    n = int(args[0]) if args else 20
    repeat = int(args[args.index("--repeat") + 1]) if "--repeat" in args else 3
    threads = int(args[args.index("--threads") + 1]) if "--threads" in args else 1
    secs, m, k = flint_product(n, repeat, threads)
    print(f"flint  N = {n}: {m} x {m} terms -> {k} terms, {threads} thread(s): "
          f"{secs:.3f} s (median of {repeat})")
    if "--sympy" in args:
        s = int(args[args.index("--sympy") + 1])
        secs, m, k = sympy_product(s, 1)
        print(f"sympy  N = {s}: {m} x {m} terms -> {k} terms: {secs:.3f} s")


if __name__ == "__main__":
    main()
