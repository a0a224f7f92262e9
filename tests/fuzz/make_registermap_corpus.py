#!/usr/bin/env python3
"""Writes the seed corpus of the register map fuzz target (corpus/registermap/): the real
map, valid variants, and broken maps that hit each of the loader's error paths. Run it again
after the map format changes; libFuzzer finds the rest from these."""
import copy
import json
import pathlib

here = pathlib.Path(__file__).resolve().parent
out = here / "corpus" / "registermap"
out.mkdir(parents=True, exist_ok=True)
real_bytes = (here / "../../resources/maps/controller.json").read_bytes()
real = json.loads(real_bytes)

T = {"en": "X", "zh_CN": "甲"}


def entry(key, plc, **extra):
    e = {"key": key, "kind": "holding", "plc": plc, "words": 1, "scale": 1, "unit": "",
         "min": 0, "max": 10, "access": "rw", "group": "g", "label": T, "help": T}
    e.update(extra)
    return e


mini = {"format": "stepcom-register-map", "schema": 1, "id": "mini", "version": 1, "name": T,
        "groups": [{"id": "g", "label": T}],
        "entries": [entry("a.one", 40001), entry("a.two", 40002)]}


def variant(name, change):
    m = copy.deepcopy(mini)
    change(m)
    (out / f"{name}.json").write_text(json.dumps(m, ensure_ascii=False, indent=1), "utf-8")


def write_raw(name, data):
    (out / name).write_bytes(data)


write_raw("controller.json", real_bytes)
write_raw("controller-compact.json", json.dumps(real, ensure_ascii=False,
                                                separators=(",", ":")).encode())
variant("mini", lambda m: None)
variant("signed-2-words-scale", lambda m: m["entries"].append(
    entry("pos", 40010, words=2, signed=True, scale=100, min=-21474836.48, max=21474836.47,
          access="r")))
variant("enum", lambda m: (m.update(enums={"dir": [{"value": 0, "label": T},
                                                   {"value": 1, "label": {"en": "1", "zh_CN": "一"}}]}),
                           m["entries"].append(entry("d", 40020, enum="dir", min=None, max=None))))
variant("coil", lambda m: m["entries"].append(
    {"key": "go", "kind": "coil", "plc": 1, "command": "motion", "group": "g", "label": T, "help": T}))
variant("block", lambda m: m.update(blocks=[{"prefix": "motor", "count": 3, "label": T, "entries": [
    dict(entry("speed", 40100, stride=10, label={"en": "Speed {n}", "zh_CN": "速度 {n}"}))]}]))
variant("scale1000", lambda m: m["entries"].append(entry("f", 40030, scale=1000, min=-32.768,
                                                         max=32.767, signed=True)))
variant("limits", lambda m: m.update(limits={"maxRegistersPerRequest": 123, "answerDelayMs": 0}))
# broken ones
variant("bad-format", lambda m: m.update(format="something-else"))
variant("bad-schema", lambda m: m.update(schema=2))
variant("huge-version", lambda m: m.update(version=1e300))
variant("duplicate-key", lambda m: m["entries"].append(entry("a.one", 40005)))
variant("overlap", lambda m: m["entries"].append(entry("b", 40002, words=2)))
variant("plc-out-of-range", lambda m: m["entries"].append(entry("c", 50000)))
variant("min-greater-than-max", lambda m: m["entries"].append(entry("c", 40007, min=5, max=1)))
variant("too-wide", lambda m: m["entries"].append(entry("c", 40007, max=70000)))
variant("unknown-fields", lambda m: (m.update(colour="red"), m["entries"][0].update(size=3)))
variant("unknown-group-enum", lambda m: m["entries"].append(entry("c", 40007, group="x", enum="y")))
variant("big-stride", lambda m: m.update(blocks=[{"prefix": "m", "count": 32, "label": T, "entries": [
    entry("s", 40001, stride=2147483647)]}]))
variant("missing-texts", lambda m: m["entries"].append(
    {"key": "c", "kind": "holding", "plc": 40009, "label": {"en": " "}, "help": 3}))
variant("wrong-types", lambda m: m.update(groups={}, entries={}, enums=[], blocks="x"))
write_raw("truncated.json", real_bytes[:1000])
write_raw("not-an-object.json", b"[1, 2, 3]\n")
write_raw("empty", b"")
write_raw("garbage.bin", bytes(range(256)))
