#!/usr/bin/env python3
# Regenerates the broken profiles of this directory from ../data/machine-a.json, with the
# message each must give (expected.tsv, read by tst_profilefile). Run from tests/core/profile.
import copy, json

good = json.load(open("data/machine-a.json"), object_pairs_hook=dict)
def dump(o): return json.dumps(o, indent=4, ensure_ascii=False) + "\n"
text = dump(good)
cases = []
def raw(name, content, expected): cases.append((name, content, expected))
def variant(name, change, expected):
    g = copy.deepcopy(good); change(g); cases.append((name, dump(g), expected))

raw("empty.json", "", "the file is empty")
raw("whitespace.json", " \n\t\n", "the file is empty")
raw("truncated.json", text[:len(text) // 2], "not valid JSON at line")
raw("trailing-comma.json", text.replace('"mode.round_trips": 0', '"mode.round_trips": 0,'), "not valid JSON at line")
raw("not-json.json", "motor1.speed = 300\n", "not valid JSON at line 1, column 1")
raw("array.json", "[1, 2, 3]\n", "JSON list, not a profile object")
raw("binary.json", "\x00\x01\x02\xff", "not valid JSON")
raw("deep-nesting.json", "[" * 5000 + "]" * 5000, "not valid JSON")
raw("nan-literal.json", text.replace('"motor1.speed": 300', '"motor1.speed": NaN'), "not valid JSON at line")
raw("overflow-number.json", text.replace('"motor1.pitch": 5', '"motor1.pitch": 1e999'), "illegal number")
raw("huge-number.json", text.replace('"motor1.pitch": 5', '"motor1.pitch": 1e300'), "motor1.pitch: 1.0000000000000001e+300 is far too large")
raw("huge-integer.json", text.replace('"motor1.speed": 300', '"motor1.speed": 123456789012345678901234567890'), "motor1.speed: 1.2345678901234568e+29 is far too large")
raw("duplicate-key.json", text.replace('"motor1.speed": 300,', '"motor1.speed": 300,\n        "motor1.speed": 3000,'), '"values": the key "motor1.speed" appears more than once')
raw("duplicate-top.json", text.replace('"schema": 1,', '"schema": 1,\n    "schema": 1,'), 'the key "schema" appears more than once')
variant("wrong-format.json", lambda g: g.update(format="something-else"), 'not a StepCom profile: "format" must be "stepcom-profile", found a text "something-else"')
variant("register-map.json", lambda g: g.update(format="stepcom-register-map"), "this is a register map, not a profile")
variant("no-format.json", lambda g: g.pop("format"), 'not a StepCom profile: "format" must be "stepcom-profile", found nothing')
variant("newer-schema.json", lambda g: g.update(schema=3), "profile schema 3 is newer than this StepCom reads (2)")
variant("schema-string.json", lambda g: g.update(schema="1"), '"schema" must be a whole number, found a text "1"')
variant("other-map.json", lambda g: g.update(map={"id": "stepper5", "version": 1}), 'the profile is for register map "stepper5" version 1, but the controller\'s map is "stepper2" version 1')
variant("other-map-version.json", lambda g: g.update(map={"id": "stepper2", "version": 7}), 'register map "stepper2" version 7, but')
variant("map-missing.json", lambda g: g.pop("map"), '"map" must be an object')
variant("unknown-top-field.json", lambda g: g.update(valeus={}), 'unknown field "valeus"')
variant("unknown-key.json", lambda g: g["values"].update({"motor3.speed": 300}), 'unknown parameter "motor3.speed"')
variant("read-only-key.json", lambda g: g["values"].update({"motor1.position": 0}), '"motor1.position" is read-only')
variant("command-key.json", lambda g: g["values"].update({"factory_reset": 1}), '"factory_reset" is a command, not a setting')
variant("missing-key.json", lambda g: g["values"].pop("motor2.pitch"), 'missing "motor2.pitch" (Pitch)')
variant("values-missing.json", lambda g: g.pop("values"), '"values" must be an object of key: value, found nothing')
variant("values-array.json", lambda g: g.update(values=[1, 2]), '"values" must be an object of key: value, found a list')
variant("wrong-type-string.json", lambda g: g["values"].update({"motor1.speed": "300"}), 'motor1.speed: expected a number, found a text "300"')
variant("wrong-type-bool.json", lambda g: g["values"].update({"motor1.direction": True}), "motor1.direction: expected a number, found true/false")
variant("wrong-type-null.json", lambda g: g["values"].update({"arc.speed": None}), "arc.speed: expected a number, found null")
variant("wrong-type-object.json", lambda g: g["values"].update({"arc.speed": {"value": 100}}), "arc.speed: expected a number, found an object")
variant("nan-string.json", lambda g: g["values"].update({"motor1.step_angle": "NaN"}), 'motor1.step_angle: expected a number, found a text "NaN"')
variant("infinity-string.json", lambda g: g["values"].update({"line.end_x": "Infinity"}), 'line.end_x: expected a number, found a text "Infinity"')
variant("out-of-range.json", lambda g: g["values"].update({"motor1.speed": 99999}), "motor1.speed: 99999 is out of range")
variant("negative.json", lambda g: g["values"].update({"motor1.microsteps": -8}), "motor1.microsteps: -8 is out of range")
variant("too-many-decimals.json", lambda g: g["values"].update({"motor1.step_angle": 1.805}), "motor1.step_angle: 1.8049999999999999 has more than 2 decimal")
variant("not-in-enum.json", lambda g: g["values"].update({"motor1.limit_positive": 7}), "motor1.limit_positive")
variant("metadata-wrong-type.json", lambda g: g["metadata"].update(name=42), '"metadata": "name" must be a text, found a number')
variant("metadata-bad-date.json", lambda g: g["metadata"].update(created="yesterday"), '"metadata": "created" is not a date and time')
variant("metadata-bad-baud.json", lambda g: g["metadata"].update(baud=1200), '"metadata": "baud" must be a')
variant("metadata-unknown.json", lambda g: g["metadata"].update(owner="me"), '"metadata": unknown field "owner"')

with open("corpus/expected.tsv", "w") as f:
    f.write("# file<TAB>a part of the error message it must give (tst_profilefile); make-corpus.py\n")
    f.write("# other-map*.json are refused only when other maps are refused (the window); stepcomctl opens them as variants\n")
    for name, content, expected in cases:
        with open("corpus/" + name, "wb") as out:
            out.write(content.encode("latin1") if name == "binary.json" else content.encode())
        f.write(f"{name}\t{expected}\n")
