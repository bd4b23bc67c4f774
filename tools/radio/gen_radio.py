#!/usr/bin/env python3
"""Makes the radio voice lines of assets/radio/lines.json: espeak-ng speaks each line with its
speaker's voice, pitch and speed; sox band-limits it to a radio's 300-3400 Hz, overdrives and
compresses it, frames it with a squelch burst and a roger beep, and writes it as an 8 kHz mono
IMA ADPCM WAV (assets/radio/ID.wav). Deterministic: sox runs with -R (fixed noise seed) and -D
(no dither). Usage: tools/radio/gen_radio.py [ROOT] [--only ID ...]   (README.md beside it)."""
import json, os, re, subprocess, sys, tempfile

RATE = 8000


def load_manifest(path):
    text = "\n".join(l for l in open(path, encoding="utf-8") if not l.lstrip().startswith("//"))
    return json.loads(text)


def sox(*args):
    subprocess.run(["sox", "-R", "-D", *args], check=True)


def make_line(line_id, line, speaker, out_dir, tmp):
    raw = os.path.join(tmp, line_id + "_raw.wav")
    subprocess.run(["espeak-ng", "-v", speaker["voice"], "-p", str(speaker["pitch"]), "-s", str(speaker["speed"]),
                    "-w", raw, line["text"]], check=True)
    voice = os.path.join(tmp, line_id + "_voice.wav")
    # The radio: espeak's silence trimmed off both ends, a narrow band, a fast leveller, drive for
    # the grit, then a look-ahead limiter, so the speech's RMS sits within about 10 dB of its peak
    # and a line carries over a ducked fight.
    sox(raw, "-r", str(RATE), "-c", "1", "-b", "16", voice,
        "silence", "1", "0.02", "-45d", "reverse", "silence", "1", "0.02", "-45d", "reverse",
        "highpass", "300", "lowpass", "3400",
        "compand", "0.001,0.02", "6:-60,-40,-40,-6,0,-3", "-4", "-90", "0.002",
        "overdrive", "20", "20", "gain", "-3", "highpass", "300", "lowpass", "3400", "rate", str(RATE),
        "compand", "0,0.03", "-20,-20,0,-20", "0", "-90", "0.003", "gain", "-n", "-1")
    squelch_in = os.path.join(tmp, line_id + "_in.wav")
    sox("-n", "-r", str(RATE), "-c", "1", "-b", "16", squelch_in, "synth", "0.07", "whitenoise",
        "bandpass", "1800", "1.5q", "fade", "0", "0.07", "0.05", "gain", "-14")
    beep = os.path.join(tmp, line_id + "_beep.wav")
    sox("-n", "-r", str(RATE), "-c", "1", "-b", "16", beep, "synth", "0.06", "sine", "1250",
        "fade", "0.005", "0.06", "0.01", "gain", "-12", "pad", "0.04", "0")
    squelch_out = os.path.join(tmp, line_id + "_out.wav")
    sox("-n", "-r", str(RATE), "-c", "1", "-b", "16", squelch_out, "synth", "0.12", "whitenoise",
        "bandpass", "1800", "1.5q", "fade", "0", "0.12", "0.1", "gain", "-16")
    out = os.path.join(out_dir, line_id + ".wav")
    sox(squelch_in, voice, beep, squelch_out, "-e", "ima-adpcm", out)
    return out


def main(argv):
    args = [a for a in argv if not a.startswith("--")]
    only = argv[argv.index("--only") + 1:] if "--only" in argv else None
    root = args[0] if args and not only else os.path.join(os.path.dirname(__file__), "..", "..")
    manifest_path = os.path.join(root, "assets", "radio", "lines.json")
    m = load_manifest(manifest_path)
    with tempfile.TemporaryDirectory() as tmp:
        for line_id, line in m["lines"].items():
            if only and line_id not in only:
                continue
            if not re.fullmatch(r"[a-z0-9_]+", line_id):
                sys.exit(f"{manifest_path}: line id '{line_id}': allowed: a-z, 0-9 and _")
            if line["speaker"] not in m["speakers"]:
                sys.exit(f"{manifest_path}: line '{line_id}': speaker '{line['speaker']}' is not in 'speakers'")
            out = make_line(line_id, line, m["speakers"][line["speaker"]], os.path.dirname(manifest_path), tmp)
            print(out, os.path.getsize(out), "bytes")


if __name__ == "__main__":
    main(sys.argv[1:])
