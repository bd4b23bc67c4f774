#!/usr/bin/env python3
"""Speed against accuracy: draws out/tradeoffs.csv (build/arcfire-bench --scene tradeoffs) into
out/tradeoffs.png.

Left: every render configuration's cost (frame time / the reference preset's, same-round median,
geometric mean over the gallery, the battle and the close-up) against its error (the worst of the
three scenes' PSNR against the reference image; higher is more accurate), the Pareto front (no
configuration both cheaper and more accurate) and the four presets marked. Right: the simulation
rows, cost (time per tick / the reference's) against how long the battle stays within 1 m of
sub-steps 16 (the AI makes it chaotic: after that the ships part by hundreds of metres).

    tools/plot_tradeoffs.py [CSV] [PNG]      (defaults: out/tradeoffs.csv out/tradeoffs.png)

Installs python3-matplotlib from Debian (apt-get) when it is missing, and runs under Debian's
/usr/bin/python3 when another python3 (pyenv, a venv) came first on PATH. Prints the front and
whether each preset lies on it; exit code 2 for a missing or malformed CSV.
"""
import csv
import os
import shutil
import subprocess
import sys


def ensure_matplotlib():
    try:
        import matplotlib  # noqa: F401
        return
    except ImportError:
        pass
    # Debian's package is for Debian's interpreter: run under it when another python3 came first on PATH.
    debian = "/usr/bin/python3"
    if os.path.realpath(sys.executable) != os.path.realpath(debian) and os.path.exists(debian):
        if subprocess.run([debian, "-c", "import matplotlib"], capture_output=True).returncode == 0:
            os.execv(debian, [debian] + sys.argv)
    sudo = [] if os.geteuid() == 0 else ["sudo"]
    if not shutil.which("apt-get") or (sudo and not shutil.which("sudo")):
        sys.exit("plot_tradeoffs.py: python3-matplotlib is missing; install it with apt-get as root")
    print("plot_tradeoffs.py: installing python3-matplotlib (apt-get)")
    subprocess.run(sudo + ["apt-get", "install", "-y", "-q", "python3-matplotlib"], check=True,
                   env=dict(os.environ, DEBIAN_FRONTEND="noninteractive"))
    if os.path.realpath(sys.executable) != os.path.realpath(debian):
        os.execv(debian, [debian] + sys.argv)


def number(row, key, path, line):
    try:
        return float(row[key])
    except (KeyError, ValueError):
        print(f"{path}:{line}: column '{key}' must be a number, got '{row.get(key)}'", file=sys.stderr)
        sys.exit(2)


def read_rows(path):
    if not os.path.isfile(path):
        print(f"{path}: no such file; run build/arcfire-bench --scene tradeoffs first", file=sys.stderr)
        sys.exit(2)
    render, sim = [], []
    with open(path, newline="") as f:
        for line, row in enumerate(csv.DictReader(f), start=2):
            kind = row.get("kind", "")
            name = "reference" if not row["setting"] else (
                "preset " + row["setting"] if kind.startswith("preset") else
                "candidate " + row["setting"] if kind == "candidate" else f"{row['setting']}={row['value']}")
            if kind in ("render", "preset", "candidate"):
                render.append((name, kind, number(row, "cost_ratio", path, line), number(row, "psnr_min_db", path, line)))
            elif kind in ("sim", "preset_sim"):
                apart = row.get("ship_diverged_after_s", "")
                apart = 10.0 if apart == "never" else number(row, "ship_diverged_after_s", path, line)
                sim.append((name, kind, number(row, "cost_ratio", path, line), apart))
            else:
                print(f"{path}:{line}: kind must be render, preset, candidate, sim or preset_sim, got '{kind}'",
                      file=sys.stderr)
                sys.exit(2)
    return render, sim


def pareto(points):
    """Points (cost, psnr) no other point beats: none both cheaper and more accurate (a tie
    in either is no win, so a preset and an identical configuration both stay on it)."""
    front = []
    for p in points:
        dominated = any(q[2] < p[2] and q[3] > p[3] for q in points)
        if not dominated:
            front.append(p)
    return sorted(front, key=lambda p: p[2])


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else "out/tradeoffs.csv"
    dst = sys.argv[2] if len(sys.argv) > 2 else "out/tradeoffs.png"
    render, sim = read_rows(src)
    ensure_matplotlib()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    front = pareto(render)
    print("Pareto front (cost, worst PSNR dB):")
    for name, _, cost, psnr in front:
        print(f"  {name:40s} x{cost:.3f} {psnr:6.2f} dB")
    for name, kind, cost, psnr in render:
        if kind == "preset":
            on = any(f[0] == name for f in front)
            print(f"{name}: x{cost:.3f}, {psnr:.2f} dB, {'on' if on else 'NOT on'} the front")

    fig, (ax, bx) = plt.subplots(1, 2, figsize=(14, 6), gridspec_kw={"width_ratios": [3, 2]})
    others = [r for r in render if r[1] == "render"]
    ax.scatter([r[2] for r in others], [r[3] for r in others], s=18, color="0.55", label="one setting changed from reference")
    whole = [r for r in render if r[1] == "candidate"]
    ax.scatter([r[2] for r in whole], [r[3] for r in whole], s=22, marker="D", color="tab:cyan", label="whole configurations (candidates)")
    for name, _, cost, psnr in others + whole:
        ax.annotate(name.replace("render.", "").replace("candidate ", ""), (cost, psnr), fontsize=6, color="0.35",
                    xytext=(3, 2), textcoords="offset points")
    ax.plot([f[2] for f in front], [f[3] for f in front], "-", color="tab:blue", lw=1.2, label="Pareto front")
    colours = {"preset low": "tab:red", "preset medium": "tab:orange", "preset high": "tab:green", "preset reference": "black"}
    for name, kind, cost, psnr in render:
        if kind == "preset":
            ax.scatter([cost], [psnr], s=90, marker="*", color=colours.get(name, "tab:purple"), zorder=5, label=name)
    ax.set_xscale("log")
    ax.set_xlabel("frame time / reference preset's (log; geometric mean of gallery, battle, close-up)")
    ax.set_ylabel("worst PSNR of the three scenes against reference (dB; 99 = identical)")
    ax.set_title("Rendering: cost against accuracy")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="lower right")

    for name, kind, cost, apart in sim:
        marker, colour = ("*", colours.get(name, "tab:purple")) if kind == "preset_sim" else ("o", "0.45")
        bx.scatter([cost], [apart], marker=marker, color=colour, s=70 if marker == "*" else 18)
        bx.annotate(name.replace("particles.", "").replace("sim.", ""), (cost, apart), fontsize=6,
                    xytext=(3, 2), textcoords="offset points")
    bx.set_xlabel("time per tick / reference preset's (arena, 600 ticks; noise about ±0.2)")
    bx.set_ylabel("seconds until a ship is 1 m from its sub-steps-16 path (10 = never)")
    bx.set_title("Simulation")
    bx.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    os.makedirs(os.path.dirname(dst) or ".", exist_ok=True)
    fig.savefig(dst, dpi=110)
    print(f"wrote {dst}")


if __name__ == "__main__":
    main()
