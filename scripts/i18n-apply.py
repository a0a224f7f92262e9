#!/usr/bin/env python3
"""Fill unfinished messages of the .ts files from tab-separated translation lists.

    cmake --build build --target update_translations     # lupdate: new strings appear unfinished
    scripts/i18n-apply.py list.tsv [more.tsv ...]         # fill them in

Each TSV line is  context<TAB>source<TAB>Simplified Chinese  (\\n and \\t escaped). English gets
the source itself; for %n messages English gets a singular and a plural form made from "(s)".
Messages still unfinished afterwards are listed, and the exit code is 1 then.
"""
import html
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TS = {"en": ROOT / "translations/stepcom_en.ts", "zh_CN": ROOT / "translations/stepcom_zh_CN.ts"}


def unescape_tsv(s):
    return s.replace("\\n", "\n").replace("\\t", "\t").replace("\\\\", "\\")


def xml_escape(s):
    return html.escape(s, quote=False).replace("'", "&apos;").replace('"', "&quot;")


def load(paths):
    table = {}
    for p in paths:
        for n, line in enumerate(Path(p).read_text(encoding="utf-8").splitlines(), 1):
            if not line.strip() or line.startswith("#"):
                continue
            parts = line.split("\t")
            if len(parts) != 3:
                sys.exit(f"{p}:{n}: expected 3 tab-separated fields, got {len(parts)}")
            ctx, src, zh = (unescape_tsv(x) for x in parts)
            table[(ctx, src)] = zh
            table.setdefault((None, src), zh)  # same text in another context
    return table


MESSAGE = re.compile(r"(<message( numerus=\"yes\")?[^>]*>)(.*?)(</message>)", re.S)
CONTEXT = re.compile(r"<context>\s*<name>(.*?)</name>(.*?)</context>", re.S)
UNFINISHED = re.compile(r"<translation type=\"unfinished\">.*?</translation>|<translation type=\"unfinished\"/>", re.S)


def translation_xml(lang, src, zh, numerus):
    if lang == "en":
        if numerus:
            one, many = src.replace("(s)", ""), src.replace("(s)", "s")
            return ("<translation>\n            <numerusform>%s</numerusform>\n"
                    "            <numerusform>%s</numerusform>\n        </translation>"
                    % (xml_escape(one), xml_escape(many)))
        return "<translation>%s</translation>" % xml_escape(src)
    if numerus:
        return ("<translation>\n            <numerusform>%s</numerusform>\n        </translation>"
                % xml_escape(zh))
    return "<translation>%s</translation>" % xml_escape(zh)


def fill(lang, path, table):
    text = path.read_text(encoding="utf-8")
    missing = []

    def on_context(cm):
        ctx = html.unescape(cm.group(1))

        def on_message(mm):
            head, numerus, body, tail = mm.groups()
            if not UNFINISHED.search(body):
                return mm.group(0)
            src = html.unescape(re.search(r"<source>(.*?)</source>", body, re.S).group(1))
            zh = table.get((ctx, src), table.get((None, src)))
            if zh is None and lang == "zh_CN":
                missing.append(f"{ctx}\t{src}")
                return mm.group(0)
            return head + UNFINISHED.sub(lambda _: translation_xml(lang, src, zh, bool(numerus)),
                                         body, count=1) + tail

        return cm.group(0).replace(cm.group(2), MESSAGE.sub(on_message, cm.group(2)))

    path.write_text(CONTEXT.sub(on_context, text), encoding="utf-8")
    return missing


def main():
    table = load(sys.argv[1:])
    missing = []
    for lang, path in TS.items():
        missing += fill(lang, path, table)
    for m in missing:
        print("untranslated:", m.replace("\n", "\\n"))
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
