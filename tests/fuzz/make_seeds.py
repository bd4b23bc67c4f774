#!/usr/bin/env python3
"""Rebuilds the seed corpora (tests/fuzz/corpus/TARGET/) and dictionaries (tests/fuzz/dict/)
from the repository's own files and its hand-written bad inputs. Run from anywhere:
    python3 tests/fuzz/make_seeds.py
The snapshot seeds come from build/fuzz_snapshot_seeds (see CMakeLists.txt) and are kept.
Findings live in tests/fuzz/regression/ and are never touched here."""
import base64, glob, json, os, re, shutil, struct

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
FUZZ = os.path.join(ROOT, "tests", "fuzz")

SEEDS = {
    "level": ["levels/*.json", "tests/replays/levels/*.json", "tests/cli/bad/truncated.json",
              "tests/cli/bad/unknown_key.json"],
    "ship_class": ["assets/ships/*.json"],
    "effect": ["assets/effects/*.json"],
    "quality": ["assets/settings/quality.json"],
    "bindings": ["assets/settings/bindings.json"],
    "replay": ["tests/replays/*.replay", "tests/replays/bad/*.replay", "tests/bench/*.replay"],
    "model_glb": ["assets/models/asteroid.glb", "assets/models/wall.glb"],
    "sprite": ["assets/textures/sprite_*.png"],
}

# Bad inputs written here, beside the copied files: each one a case a loader must refuse cleanly.
BAD = {
    "level": {"bad_nested.json": "[" * 64, "bad_nan.json": '{"name": "x", "seed": NaN}',
              "bad_empty.json": ""},
    "ship_class": {"bad_type.json": '{"model": 3, "mass": "heavy"}'},
    "effect": {"bad_curve.json": '{"emitters": [{"curves": {"size": [[0, 1], [0.5]]}}]}'},
    "quality": {"bad_presets.json": '{"presets": [1, 2]}', "bad_root.json": "[]"},
    "bindings": {"bad_key.json": '{"keyboard": {"fire_primary": "MOUSE_LEFTT"}}'},
    "replay": {"bad_header.replay": "arcfire-replay 999\n", "bad_tick.replay": "arcfire-replay 1\nlevel x\n-1 input\n",
               "match_v2.replay": "arcfire-replay 2\nlevel levels/duel.json\nseed 2202\nslots 2\npilot 0 Host\npilot 1 \"Red Two\"\ndrop 1 90\n0 axis throttle 0.5\n0 slot 1 press fire_primary\n+5 slot 1 command countermeasure\n60 hash ?\n120 end\n"},
    "model_gltf": {"bad_uri.gltf": '{"asset": {"version": "2.0"}, "buffers": [{"byteLength": 4, "uri": "/dev/zero"}]}'},
    "model_glb": {"bad_length.glb": b"glTF\x02\x00\x00\x00\xff\xff\xff\x7f"},
    "sprite": {"bad_header.png": b"\x89PNG\r\n\x1a\n\x00\x00\x00\x0dIHDR\x7f\xff\xff\xff\x7f\xff\xff\xff\x08\x06\x00\x00\x00"},
}

# glTF files that are not what they claim (assets/gltf_claims.h): one triangle in a data URI with
# its version, nodes, position count or required extensions changed.
GLTF_TRIANGLE = ('{"asset": ASSET, "scenes": [{"nodes": [0]}], "nodes": NODES, "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}], "buffers": [{"uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIA", "byteLength": 42}], "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}], "accessors": [{"bufferView": 0, "componentType": 5126, "count": COUNT, "type": "VEC3"}, {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]EXTRA}')


def gltf_claim(asset='{"version": "2.0"}', nodes='[{"mesh": 0}]', count="3", extra=""):
    return (GLTF_TRIANGLE.replace("ASSET", asset).replace("NODES", nodes).replace("COUNT", count)
            .replace("EXTRA", extra))


BAD["model_gltf"].update({
    "bad_version_1.gltf": gltf_claim(asset='{"version": "1.0"}'),
    "bad_draco_required.gltf": gltf_claim(extra=', "extensionsRequired": ["KHR_draco_mesh_compression"]'),
    "bad_zero_positions.gltf": gltf_claim(count="0"),
    "bad_scale_overflow.gltf": gltf_claim(nodes='[{"name": "hull", "scale": [1e30, 1e30, 1e30], "children": [1]}, '
                                                '{"name": "wing", "scale": [1e30, 1e30, 1e30], "mesh": 0}]'),
})


def glb_to_gltf(path):
    """The same model as a .gltf with its BIN chunk as a base64 data URI."""
    data = open(path, "rb").read()
    json_len = struct.unpack_from("<I", data, 12)[0]
    doc = json.loads(data[20:20 + json_len])
    at = 20 + json_len
    bin_len = struct.unpack_from("<I", data, at)[0]
    binary = data[at + 8:at + 8 + bin_len]
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(binary).decode()
    return json.dumps(doc)


def json_words(paths):
    words = set()
    for p in paths:
        try:
            text = open(p, encoding="utf-8").read()
        except (UnicodeDecodeError, IsADirectoryError):
            continue
        words.update(re.findall(r'"([A-Za-z_][A-Za-z0-9_.]{0,40})"', text))
    return words


def write_dict(name, words, tokens):
    with open(os.path.join(FUZZ, "dict", name + ".dict"), "w") as f:
        f.write("# " + name + ": tokens and keywords of the format (tests/fuzz/make_seeds.py)\n")
        for t in tokens:
            f.write(t + "\n")
        for w in sorted(words):
            f.write('"\\"%s\\""\n' % w)


def main():
    os.makedirs(os.path.join(FUZZ, "dict"), exist_ok=True)
    json_tokens = ['"{"', '"}"', '"["', '"]"', '":"', '","', '"true"', '"false"', '"null"', '"-1e309"',
                   '"1e308"', '"NaN"', '"//"', '"/*"', '"*/"', '"\\\\u0000"', '"0.5"', '"-0"']
    for target in list(SEEDS) + ["model_gltf"]:
        d = os.path.join(FUZZ, "corpus", target)
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
        files = [f for pat in SEEDS.get(target, []) for f in sorted(glob.glob(os.path.join(ROOT, pat)))]
        for f in files:
            shutil.copy(f, os.path.join(d, os.path.basename(f)))
        for name, content in BAD.get(target, {}).items():
            mode = "wb" if isinstance(content, bytes) else "w"
            with open(os.path.join(d, name), mode) as out:
                out.write(content)
        if target == "model_gltf":
            for glb in ["asteroid", "wall"]:
                with open(os.path.join(d, glb + ".gltf"), "w") as out:
                    out.write(glb_to_gltf(os.path.join(ROOT, "assets/models", glb + ".glb")))
        if target in ("level", "ship_class", "effect", "quality", "bindings", "model_gltf"):
            words = json_words(glob.glob(os.path.join(d, "*")))
            if target == "level":
                words |= json_words(glob.glob(os.path.join(ROOT, "levels/README.md")))
            if target == "effect":
                words |= json_words(glob.glob(os.path.join(ROOT, "assets/effects/README.md")))
            write_dict(target, words, json_tokens)
    replay_words = set()
    for f in glob.glob(os.path.join(FUZZ, "corpus", "replay", "*")):
        for line in open(f, encoding="utf-8", errors="replace"):
            replay_words.update(w for w in line.split()[:3] if re.fullmatch(r"[A-Za-z_][A-Za-z0-9_.=-]{0,40}", w))
    with open(os.path.join(FUZZ, "dict", "replay.dict"), "w") as out:
        out.write("# replay: keywords of the script format (tests/fuzz/make_seeds.py)\n")
        for t in ['"\\x0a"', '" "', '"#"', '"arcfire-replay 1\\x0a"', '"18446744073709551616"', '"-1"', '"nan"', '"1e999"']:
            out.write(t + "\n")
        for w in sorted(replay_words):
            out.write('"%s"\n' % w)
    binary = {
        "model_glb": ['"glTF"', '"JSON"', '"BIN\\x00"', '"\\x02\\x00\\x00\\x00"', '"\\xff\\xff\\xff\\xff"'],
        "sprite": ['"\\x89PNG\\x0d\\x0a\\x1a\\x0a"', '"IHDR"', '"IDAT"', '"IEND"', '"PLTE"', '"tRNS"', '"gAMA"',
                   '"iCCP"', '"sRGB"', '"zTXt"', '"\\x00\\x00\\x40\\x00"', '"\\x08\\x06\\x00\\x00\\x00"'],
        "snapshot": ['"ARCSNAP1"', '"ARCPWRLD"', '"\\x00\\x00\\x00\\x00"', '"\\xff\\xff\\xff\\xff"',
                     '"\\xff\\xff\\xff\\xff\\xff\\xff\\xff\\x7f"', '"\\x00\\x00\\xf8\\x7f"'],
    }
    glb_words = json_words(glob.glob(os.path.join(FUZZ, "corpus", "model_gltf", "*")))
    for name, tokens in binary.items():
        write_dict(name, glb_words if name == "model_glb" else set(), tokens)


if __name__ == "__main__":
    main()
