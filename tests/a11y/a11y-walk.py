#!/usr/bin/python3
"""The window as a screen reader sees it: starts the real `stepcom --sim` under Xvfb
at a given screen size and language, with a private D-Bus session and the AT-SPI bus, and visits
every page by choosing its sidebar entry through the accessibility interface. On each page it
checks, from outside the process, what the accessibility bus says:

  - every showing label, text field and button lies inside what its ancestors show of it (not
    cut, not running past a dock, the machine strip or the window), unless an ancestor scrolls
    in that direction;
  - every showing button, field, box and slider has a name;
  - both motor positions and the E-STOP of the machine strip are showing, whole, inside the
    strip, the window and the screen, and the positions are known (not "—"); that E-STOP is
    the only one showing (a second, elsewhere, would be a second place to reach for);
  - the window's parts (menu bar, toolbar, docks, page area, status bar) do not overlap.

A report per screen and language; the exit status is 1 on any finding, 2 when the program could
not be walked (it never appeared on the bus, a page could not be chosen), 77 when the
accessibility stack (python3-pyatspi, at-spi2-core, Xvfb, dbus-daemon) is not installed
(scripts/deps.sh --test installs it). Run with /usr/bin/python3 (Debian's pyatspi).

  tests/a11y/a11y-walk.py --stepcom build/app/stepcom --size 1024x600 --lang zh_CN
  tests/a11y/a11y-walk.py --stepcom build/app/stepcom --all --shots /tmp/a11y   # every size

A size may carry a scale: 1366x768@1.5 runs with QT_SCALE_FACTOR=1.5. docs/testing.md says more.
"""

import argparse
import os
import re
import select
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

SKIP = 77
ALL_SIZES = ["1024x600", "1280x800", "1366x768", "1366x768@1.5", "1920x1080"]
ALL_LANGS = ["en", "zh_CN"]
HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))

# Roles whose text must be seen whole; buttons must be whole and named too.
TEXT_ROLES = {"label", "text", "heading", "static", "caption", "paragraph"}
BUTTON_ROLES = {"push button", "toggle button", "check box", "radio button", "push button menu"}
# What a user operates: a screen reader must be able to say what it is.
CONTROL_ROLES = BUTTON_ROLES | {"text", "combo box", "spin button", "slider", "password text"}
# Their children change with every poll (traffic rows, messages): their own extents are
# checked, what they hold is the view's to scroll and elide.
ITEM_VIEW_ROLES = {"table", "tree table", "list", "tree", "list box"}
OPAQUE_ROLES = ITEM_VIEW_ROLES | {"menu bar", "page tab list", "combo box", "spin button",
                                  "tool bar"}
SLACK = 1  # px: rounding of scaled geometry


def log(*args):
    print(*args, flush=True)


# --------------------------------------------------------------------------- the parent side


def find_bus_launcher():
    for path in ("/usr/libexec/at-spi-bus-launcher", "/usr/lib/at-spi2-core/at-spi-bus-launcher",
                 "/usr/lib/at-spi2/at-spi-bus-launcher"):
        if os.access(path, os.X_OK):
            return path
    return None


def missing_stack():
    """What of the accessibility stack is missing, in words; empty when all is there."""
    missing = []
    probe = subprocess.run([sys.executable, "-c", "import gi; gi.require_version('Atspi', '2.0');"
                            "from gi.repository import Atspi; import pyatspi"],
                           capture_output=True, text=True)
    if probe.returncode != 0:
        missing.append("python3-pyatspi (for %s)" % sys.executable)
    if not find_bus_launcher():
        missing.append("at-spi2-core (at-spi-bus-launcher)")
    for tool, package in (("Xvfb", "xvfb"), ("dbus-daemon", "dbus-daemon"),
                          ("dbus-send", "dbus-bin")):
        if not shutil.which(tool):
            missing.append("%s (%s)" % (package, tool))
    return missing


def read_line(stream, timeout, what):
    """One line from a pipe, or an error naming `what` after `timeout` seconds."""
    deadline = time.monotonic() + timeout
    data = b""
    while not data.endswith(b"\n"):
        left = deadline - time.monotonic()
        if left <= 0 or not select.select([stream], [], [], left)[0]:
            raise RuntimeError("%s: nothing after %d s" % (what, timeout))
        chunk = os.read(stream.fileno(), 1)
        if not chunk:
            raise RuntimeError("%s ended without saying it was ready" % what)
        data += chunk
    return data.decode().strip()


class Session:
    """Xvfb, a private session bus and the AT-SPI bus for one run; every process in a group
    of its own, ended by its id."""

    def __init__(self, size, scale, workdir):
        self.size, self.scale, self.workdir = size, scale, workdir
        self.procs = []

    def start(self, name, argv, env=None, **kwargs):
        out = open(os.path.join(self.workdir, name + ".log"), "wb")
        proc = subprocess.Popen(argv, env=env, stderr=out, start_new_session=True, **kwargs)
        self.procs.append(proc)
        return proc

    def up(self):
        w, h = self.size
        xvfb = self.start("xvfb", ["Xvfb", "-displayfd", "1", "-screen", "0", "%dx%dx24" % (w, h),
                                   "-nolisten", "tcp", "-noreset"], stdout=subprocess.PIPE)
        self.display = ":" + read_line(xvfb.stdout, 30, "Xvfb")
        dbus = self.start("dbus", ["dbus-daemon", "--session", "--nofork", "--print-address"],
                          stdout=subprocess.PIPE)
        self.bus = read_line(dbus.stdout, 30, "dbus-daemon")
        self.env = dict(os.environ)
        for var in ("WAYLAND_DISPLAY", "QT_QPA_PLATFORM", "QT_SCALE_FACTOR", "AT_SPI_BUS_ADDRESS",
                    "QT_ACCESSIBILITY", "NO_AT_BRIDGE", "XAUTHORITY", "SESSION_MANAGER"):
            self.env.pop(var, None)
        home = os.path.join(self.workdir, "home")
        runtime = os.path.join(self.workdir, "runtime")
        os.makedirs(home)
        os.makedirs(runtime, mode=0o700)
        self.env.update(DISPLAY=self.display, DBUS_SESSION_BUS_ADDRESS=self.bus, HOME=home,
                        XDG_RUNTIME_DIR=runtime, XDG_CONFIG_HOME=os.path.join(home, ".config"),
                        XDG_DATA_HOME=os.path.join(home, ".local/share"),
                        XDG_CACHE_HOME=os.path.join(home, ".cache"), LC_ALL="C.UTF-8",
                        QT_LINUX_ACCESSIBILITY_ALWAYS_ON="1", QT_ACCESSIBILITY="1")
        self.start("at-spi-bus-launcher", [find_bus_launcher(), "--launch-immediately"],
                   env=self.env, stdout=subprocess.DEVNULL)
        # The program asks the session bus for the accessibility bus when it starts: the
        # launcher must own its name by then, or the program never shows on it.
        deadline = time.monotonic() + 60
        while True:
            owned = subprocess.run(
                ["dbus-send", "--session", "--print-reply", "--dest=org.freedesktop.DBus", "/",
                 "org.freedesktop.DBus.NameHasOwner", "string:org.a11y.Bus"],
                env=self.env, capture_output=True, text=True)
            if "boolean true" in owned.stdout:
                break
            if time.monotonic() > deadline:
                raise RuntimeError("at-spi-bus-launcher never took org.a11y.Bus on the session bus")
            time.sleep(0.2)

    def down(self):
        for proc in reversed(self.procs):
            if proc.poll() is None:
                try:
                    os.killpg(proc.pid, signal.SIGTERM)
                except ProcessLookupError:
                    pass
        for proc in reversed(self.procs):
            try:
                proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                try:
                    os.killpg(proc.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                proc.wait()


def run_one(args, size_text, lang):
    """One screen size and language: 0 clean, 1 findings, 2 not walked."""
    m = re.fullmatch(r"(\d+)x(\d+)(?:@([0-9.]+))?", size_text)
    if not m:
        log("a11y-walk: bad size %r: write WxH or WxH@scale, as 1366x768@1.5" % size_text)
        return 2
    size = (int(m.group(1)), int(m.group(2)))
    scale = m.group(3)
    title = "%s%s %s" % ("%dx%d" % size, " x" + scale if scale else "", lang)
    workdir = tempfile.mkdtemp(prefix="stepcom-a11y-")
    session = Session(size, scale, workdir)
    started = time.monotonic()
    try:
        session.up()
        env = dict(session.env)
        if scale:
            env["QT_SCALE_FACTOR"] = scale
        start_args = shlex.split(args.app_args) if args.app_args else ["--sim"]
        app = session.start("stepcom", [args.stepcom] + start_args + ["--lang", lang], env=env,
                            stdout=subprocess.DEVNULL)
        walker = [sys.executable, os.path.abspath(__file__), "--walk", str(app.pid),
                  "--lang", lang, "--screen", "%dx%d" % size, "--title", title,
                  "--startup", str(args.startup)]
        if args.shots:
            walker += ["--shots", os.path.abspath(args.shots)]
        if args.dump:
            walker += ["--dump", os.path.abspath(args.dump)]
        try:
            result = subprocess.run(walker, env=session.env, timeout=args.timeout)
            code = result.returncode
        except subprocess.TimeoutExpired:
            log("%s: the walk took more than %d s" % (title, args.timeout))
            code = 2
        if app.poll() is not None:
            log("%s: stepcom ended during the walk (exit %s)" % (title, app.returncode))
            code = 2
    except (RuntimeError, OSError) as e:
        log("%s: could not start: %s" % (title, e))
        code = 2
    finally:
        session.down()
    if code == 2:
        for name in ("stepcom", "at-spi-bus-launcher"):
            path = os.path.join(workdir, name + ".log")
            if os.path.exists(path):
                with open(path, errors="replace") as f:
                    tail = f.read()[-2000:]
                if tail.strip():
                    log("--- %s's output (last lines):\n%s" % (name, tail))
    log("%s: %s in %.0f s" % (title, {0: "no finding", 1: "FINDINGS"}.get(code, "NOT WALKED"),
                               time.monotonic() - started))
    shutil.rmtree(workdir, ignore_errors=True)
    return code


# --------------------------------------------------------------------------- the walker side


def translation(lang, context, source):
    """`source` as the program says it in `lang`, from translations/stepcom_LANG.ts."""
    if lang == "en":
        return source
    path = os.path.join(SOURCE, "translations", "stepcom_%s.ts" % lang)
    for ctx in ET.parse(path).getroot().iter("context"):
        if ctx.findtext("name") != context:
            continue
        for message in ctx.iter("message"):
            if message.findtext("source") == source:
                text = message.findtext("translation")
                if text:
                    return text
    raise RuntimeError("no %s translation of %s %r in %s" % (lang, context, source, path))


def pattern_of(text):
    """A regex for a translated "%1 ... %2" text: each %n any text."""
    return re.compile("^" + re.sub(r"%\d", "(.*)", re.escape(text).replace(r"\%", "%")) + "$",
                      re.S)


class Walker:
    def __init__(self, opts):
        import gi
        gi.require_version("Atspi", "2.0")
        import pyatspi
        self.at = pyatspi
        self.opts = opts
        self.pid = opts.walk
        self.screen = tuple(int(v) for v in opts.screen.split("x"))
        self.position = pattern_of(translation(opts.lang, "stepcom::MachineStrip",
                                               "Motor %1 position: %2"))
        self.estop = translation(opts.lang, "stepcom::EmergencyStop", "E-STOP")
        self.findings = {}  # key -> (text, [pages])
        self.pages = []
        self.notes = []
        self.axes_seen = {}  # object -> scrolls(object), for the page being checked

    # ---- small, failure-tolerant reads (objects go away while a page refreshes)
    def role(self, o):
        try:
            return o.getRoleName()
        except Exception:
            return None

    def name(self, o):
        try:
            return o.name or ""
        except Exception:
            return ""

    def states(self, o):
        try:
            return o.getState()
        except Exception:
            return None

    def showing(self, o):
        st = self.states(o)
        return bool(st) and st.contains(self.at.STATE_SHOWING) and st.contains(self.at.STATE_VISIBLE)

    def extents(self, o):
        try:
            e = o.queryComponent().getExtents(self.at.DESKTOP_COORDS)
            return (e.x, e.y, e.x + e.width, e.y + e.height)
        except Exception:
            return None

    def children(self, o):
        try:
            return [c for c in o if c is not None]
        except Exception:
            return []

    def finding(self, page, text):
        # One finding per thing, with the pages it is seen on; numbers that move (positions,
        # rates, counts) do not make it another.
        key = re.sub(r"\d+(\.\d+)?", "#", text)
        if key not in self.findings:
            self.findings[key] = (text, [], {})
        pages, counts = self.findings[key][1], self.findings[key][2]
        if page not in pages:
            pages.append(page)
        counts[page] = counts.get(page, 0) + 1

    # ---- finding the program
    def app(self):
        desktop = self.at.Registry.getDesktop(0)
        for a in self.children(desktop):
            try:
                if a.get_process_id() == self.pid:
                    return a
            except Exception:
                continue
        return None

    def wait(self, what, seconds, probe):
        deadline = time.monotonic() + seconds
        while True:
            value = probe()
            if value:
                return value
            if time.monotonic() > deadline:
                raise RuntimeError("%s: not after %d s" % (what, seconds))
            time.sleep(0.25)

    def window(self):
        app = self.app()
        if not app:
            return None
        for f in self.children(app):
            e = self.extents(f)
            if self.role(f) == "frame" and self.showing(f) and e and e[2] - e[0] > 100:
                return f
        return None

    def find(self, root, predicate, prune_hidden=True):
        """What matches `predicate` under `root`, never inside an item view: a table's or a
        list's children are its cells, every row of its model (the traffic view listening
        beside a PLC holds thousands), each a round trip on the bus to list and to ask."""
        out, todo = [], [root]
        while todo:
            o = todo.pop()
            if prune_hidden and o is not root and not self.showing(o):
                continue
            if predicate(o):
                out.append(o)
            if o is root or self.role(o) not in ITEM_VIEW_ROLES:
                todo.extend(self.children(o))
        return out

    def sidebar(self, frame):
        # The pages' list: the list beside the page stack in the page area's splitter.
        lists = self.find(frame, lambda o: self.role(o) == "list" and
                          self.role(o.parent) == "split pane")
        if len(lists) != 1:
            raise RuntimeError("the sidebar: %d lists beside the pages" % len(lists))
        return lists[0]

    def stack(self, frame):
        stacks = self.find(frame, lambda o: self.role(o) == "layered pane" and
                           self.role(o.parent) == "split pane")
        if len(stacks) != 1:
            raise RuntimeError("the page stack: %d found" % len(stacks))
        return stacks[0]

    def shown_page(self, stack):
        shown = [i for i, c in enumerate(self.children(stack)) if self.showing(c)]
        return shown[0] if len(shown) == 1 else None

    def strip_parts(self, frame):
        positions = {}
        estops = []
        for o in self.find(frame, lambda o: self.role(o) in ("label", "push button")):
            name = self.name(o)
            m = self.position.match(name)
            if self.role(o) == "label" and m:
                positions[m.group(1)] = (o, m.group(2))
            elif self.role(o) == "push button" and name == self.estop:
                estops.append(o)
        return positions, estops

    def known_positions(self, frame):
        values = [v.strip() for _, v in self.strip_parts(frame)[0].values()]
        return len(values) >= 2 and all(v and v != "—" for v in values)

    def settle(self, frame):
        """Until the window's parts stop moving (a layout pass, a dock arranged)."""
        last = None
        for _ in range(40):
            now = [self.extents(c) for c in self.children(frame) if self.showing(c)]
            if now == last:
                return
            last = now
            time.sleep(0.3)

    # ---- the checks
    def axes(self, o):
        """scrolls(o), asked once a page: it lists the children of `o` and of its parent, so
        asked for every object it lists every sibling again for each."""
        if o not in self.axes_seen:
            self.axes_seen[o] = self.scrolls(o)
        return self.axes_seen[o]

    def scrolls(self, o):
        """The axes in which `o` scrolls what it holds: a showing scroll bar among its children
        or its parent's (a scroll area's viewport holds the content), or in a plain widget
        there (a scroll area keeps its bars in containers of their own)."""
        axes = set()
        for holder in (o, getattr(o, "parent", None)):
            if holder is None:
                continue
            bars = []
            for c in self.children(holder):
                if self.role(c) == "filler":
                    bars.extend(self.children(c))
                else:
                    bars.append(c)
            for c in bars:
                if self.role(c) == "scroll bar" and self.showing(c):
                    e = self.extents(c)
                    if e:
                        axes.add("y" if e[3] - e[1] > e[2] - e[0] else "x")
        return axes

    def describe(self, o, e):
        role, name = self.role(o), self.name(o)
        label = name.replace("\n", " ")
        if len(label) > 70:
            label = label[:67] + "…"
        return "%s %s (%d,%d %dx%d)" % (role, '"%s"' % label if label else "without a name",
                                        e[0], e[1], e[2] - e[0], e[3] - e[1])

    def check_tree(self, page, o, chain):
        """`chain`: the ancestors as (object, extents, None, name)."""
        role = self.role(o)
        e = self.extents(o)
        if e is None or role is None:
            return
        if role == "frame" and chain and len(chain) == 1:
            # A dock. A dock tabbed behind another still says it is showing, far off the window
            # (Qt 6.4.2): what is not in the window is not seen.
            w = chain[0][1]
            if e[2] <= w[0] or e[0] >= w[2] or e[3] <= w[1] or e[1] >= w[3]:
                return
        if role in TEXT_ROLES | BUTTON_ROLES and (e[2] > e[0] and e[3] > e[1]):
            self.check_inside(page, o, e, chain)
        if role in CONTROL_ROLES and not self.name(o).strip():
            where = chain[-1][3] if chain else ""
            self.finding(page, "no name: %s in %s" % (self.describe(o, e), where))
        if role in OPAQUE_ROLES:
            return
        if not chain:
            where = "the window"
        elif role == "filler":  # a plain widget: named after what holds it
            where = chain[-1][3]
        else:
            where = self.describe(o, e)
        entry = (o, e, None, where)  # what scrolls is asked only when something runs past
        for c in self.children(o):
            if self.showing(c):
                self.check_tree(page, c, chain + [entry])

    def check_inside(self, page, o, e, chain):
        cut = self.cut(o, e, chain)
        if not cut:
            return
        # Read again after a moment: a status text that changed its width moves its neighbours
        # between two reads, and a part read before and after that seems to be cut.
        time.sleep(0.3)
        fresh = [(anc, self.extents(anc), axes, aname) for anc, _, axes, aname in chain]
        e = self.extents(o)
        if e and all(a for _, a, _, _ in fresh):
            cut = self.cut(o, e, fresh)
            if cut:
                self.finding(page, cut)

    def cut(self, o, e, chain):
        """What cuts `o`: the nearest ancestor it runs past in a direction nothing between
        them scrolls, in words; None when it is whole."""
        scrolling = set()
        nearest = list(reversed(chain))
        known = 0  # the nearest ancestors whose scrolling is in `scrolling`
        for k, (anc, a, _, aname) in enumerate(nearest):
            past = []
            if e[2] > a[2] + SLACK:
                past.append(("x", "%d px past its right edge" % (e[2] - a[2])))
            if e[0] < a[0] - SLACK:
                past.append(("x", "%d px past its left edge" % (a[0] - e[0])))
            if e[3] > a[3] + SLACK:
                past.append(("y", "%d px past its bottom" % (e[3] - a[3])))
            if e[1] < a[1] - SLACK:
                past.append(("y", "%d px past its top" % (a[1] - e[1])))
            if not past:
                continue
            # What scrolls between `o` and here may hide its content in that direction.
            while known <= k:
                scrolling |= self.axes(nearest[known][0])
                known += 1
            side = [text for axis, text in past if axis not in scrolling]
            if side:
                return "cut: %s runs %s of %s" % (self.describe(o, e), " and ".join(side), aname)
        return None

    def check_screen(self, page, frame):
        w = self.extents(frame)
        sw, sh = self.screen
        if w[0] < 0 or w[1] < 0 or w[2] > sw or w[3] > sh:
            self.finding(page, "the window (%d,%d %dx%d) is not inside the %dx%d screen"
                         % (w[0], w[1], w[2] - w[0], w[3] - w[1], sw, sh))
        # The window's parts side by side, never over each other (a tab bar sits on its docks).
        parts = []
        for c in self.children(frame):
            e = self.extents(c)
            if not self.showing(c) or not e or e[2] <= e[0] or e[3] <= e[1]:
                continue
            if e[2] <= w[0] or e[0] >= w[2] or e[3] <= w[1] or e[1] >= w[3]:
                continue  # a dock tabbed behind another
            parts.append((c, e))
        for i, (a, ea) in enumerate(parts):
            for b, eb in parts[i + 1:]:
                if self.role(a) == "page tab list" or self.role(b) == "page tab list":
                    continue
                ox = min(ea[2], eb[2]) - max(ea[0], eb[0])
                oy = min(ea[3], eb[3]) - max(ea[1], eb[1])
                if ox > SLACK and oy > SLACK:
                    self.finding(page, "overlap: %s and %s" % (self.describe(a, ea),
                                                               self.describe(b, eb)))

    def check_strip(self, page, frame):
        positions, estops = self.strip_parts(frame)
        w = self.extents(frame)
        strip = None
        for motor in ("1", "2"):
            if motor not in positions:
                self.finding(page, "motor %s's position is not showing" % motor)
                continue
            o, value = positions[motor]
            e = self.extents(o)
            strip = o.parent
            if value.strip() in ("", "—"):
                self.finding(page, "motor %s's position is not known (%r)" % (motor, value))
            self.check_sane(page, "motor %s's position" % motor, o, e, strip, w)
        in_strip = [b for b in estops if strip is not None and b.parent == strip]
        if not in_strip:
            self.finding(page, "the machine strip's E-STOP (%s) is not showing" % self.estop)
        elsewhere = [b for b in estops if b not in in_strip and self.showing(b)]
        if elsewhere:
            self.finding(page, "%d E-STOP(s) besides the strip's are showing: %s" % (
                len(elsewhere), ", ".join(self.describe(b, self.extents(b)) for b in elsewhere)))
        for b in in_strip:
            self.check_sane(page, "the E-STOP", b, self.extents(b), strip, w)

    def check_sane(self, page, what, o, e, strip, window):
        s = self.extents(strip)
        sw, sh = self.screen
        if not e or e[2] - e[0] < 16 or e[3] - e[1] < 10:
            self.finding(page, "%s is too small to see: %s" % (what, self.describe(o, e or (0,) * 4)))
            return
        for box, name in ((s, "the machine strip"), (window, "the window"),
                          ((0, 0, sw, sh), "the screen")):
            if box and (e[0] < box[0] - SLACK or e[1] < box[1] - SLACK or
                        e[2] > box[2] + SLACK or e[3] > box[3] + SLACK):
                self.finding(page, "%s is not inside %s: %s" % (what, name, self.describe(o, e)))

    def shoot(self, page_number, title):
        if not self.opts.shots or not shutil.which("import"):
            return
        os.makedirs(self.opts.shots, exist_ok=True)
        stem = re.sub(r"[^A-Za-z0-9_.@-]+", "-", "%s-%02d" % (self.opts.title, page_number))
        subprocess.run(["import", "-window", "root",
                        os.path.join(self.opts.shots, stem + ".png")], capture_output=True)

    def dump(self, page_number, frame):
        """The showing tree of the page, one object a line (--dump): what the bus says."""
        if not self.opts.dump:
            return
        os.makedirs(self.opts.dump, exist_ok=True)
        stem = re.sub(r"[^A-Za-z0-9_.@-]+", "-", "%s-%02d" % (self.opts.title, page_number))
        with open(os.path.join(self.opts.dump, stem + ".txt"), "w") as out:
            todo = [(frame, 0)]
            while todo:
                o, depth = todo.pop()
                e = self.extents(o) or (0, 0, 0, 0)
                out.write("%s%s\n" % ("  " * depth, self.describe(o, e)))
                if self.role(o) not in OPAQUE_ROLES:
                    todo.extend((c, depth + 1) for c in reversed(self.children(o))
                                if self.showing(c))

    # ---- the walk
    def walk(self):
        frame = self.wait("stepcom on the accessibility bus", self.opts.startup, self.window)
        self.wait("both motor positions known (the simulator answering)", self.opts.startup,
                  lambda: self.known_positions(frame))
        self.settle(frame)
        sidebar = self.sidebar(frame)
        stack = self.stack(frame)
        entries = [(i, self.name(it)) for i, it in enumerate(self.children(sidebar))
                   if self.states(it) and self.states(it).contains(self.at.STATE_SELECTABLE)]
        if not entries:
            raise RuntimeError("the sidebar has no entry to choose")
        # The page shown at the start first: it is walked even when choosing fails.
        entries.sort(key=lambda entry: not self.states(self.children(sidebar)[entry[0]]).contains(
            self.at.STATE_SELECTED))
        for number, (row, title) in enumerate(entries):
            item = self.children(sidebar)[row]
            before = self.shown_page(stack)
            was_selected = self.states(item).contains(self.at.STATE_SELECTED)
            # As a screen reader chooses an entry of a list: the item's own action.
            action = item.queryAction()
            names = [action.getName(k) for k in range(action.nActions)]
            if not was_selected:
                if "Toggle" in names:
                    action.doAction(names.index("Toggle"))
                else:
                    sidebar.queryTable().addRowSelection(row)
            try:
                self.wait("the page of %r after choosing it" % title, 20,
                          lambda: self.states(self.children(sidebar)[row]).contains(
                              self.at.STATE_SELECTED) and
                          (was_selected or self.shown_page(stack) not in (None, before)))
            except RuntimeError as e:
                self.finding(title, "the sidebar: choosing %r through the accessibility "
                             "interface does not show its page (%s)" % (title, e))
                continue
            self.settle(frame)
            self.pages.append(title)
            self.check_screen(title, frame)
            self.check_strip(title, frame)
            self.axes_seen = {}
            self.check_tree(title, frame, [])
            self.shoot(number, title)
            self.dump(number, frame)

    def report(self):
        log("%s: %d pages walked: %s" % (self.opts.title, len(self.pages), ", ".join(self.pages)))
        for text, pages, counts in self.findings.values():
            where = ("every page" if len(pages) == len(self.pages) and len(pages) > 1
                     else ", ".join(pages))
            alike = max(counts.values())
            log("  FINDING (%s): %s%s" % (where, text, " (%d alike)" % alike if alike > 1 else ""))
        return 1 if self.findings else 0


def walk_main(opts):
    try:
        walker = Walker(opts)
        walker.walk()
    except RuntimeError as e:
        log("%s: %s" % (opts.title, e))
        return 2
    return walker.report()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--stepcom", default=os.path.join(SOURCE, "build", "app", "stepcom"),
                        help="the program to walk (default: build/app/stepcom)")
    parser.add_argument("--size", action="append", help="screen WxH[@scale]; more than once")
    parser.add_argument("--lang", action="append", choices=ALL_LANGS, help="en or zh_CN")
    parser.add_argument("--all", action="store_true",
                        help="every size (%s) in both languages" % ", ".join(ALL_SIZES))
    parser.add_argument("--shots", help="a screenshot of every page into this folder")
    parser.add_argument("--dump", help="the showing objects of every page, as text, into this "
                        "folder")
    parser.add_argument("--timeout", type=int, default=300, help="seconds for one walk")
    parser.add_argument("--app-args", metavar="ARGS",
                        help="how stepcom starts instead of --sim, one string (e.g. "
                             "--app-args='--port P --listen': the window listening beside "
                             "another master)")
    parser.add_argument("--startup", type=int, default=90,
                        help="seconds to wait for the program on the bus and connected")
    parser.add_argument("--walk", type=int, help=argparse.SUPPRESS)
    parser.add_argument("--screen", help=argparse.SUPPRESS)
    parser.add_argument("--title", help=argparse.SUPPRESS)
    opts = parser.parse_args()
    if opts.walk:
        opts.lang = opts.lang[0]
        return walk_main(opts)

    # Ended from outside (ctest's timeout, Ctrl+C): still end what was started.
    for sig in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
        signal.signal(sig, lambda number, frame: sys.exit(128 + number))
    missing = missing_stack()
    if missing:
        log("a11y-walk: SKIPPED, the accessibility stack is not installed: %s "
            "(scripts/deps.sh --test installs it)" % ", ".join(missing))
        return SKIP
    if not os.access(opts.stepcom, os.X_OK):
        log("a11y-walk: no program at %s (build it, or name it with --stepcom)" % opts.stepcom)
        return 2
    sizes = ALL_SIZES if opts.all else (opts.size or ["1280x800"])
    langs = ALL_LANGS if opts.all and not opts.lang else (opts.lang or ["en"])
    worst = 0
    for size in sizes:
        for lang in langs:
            worst = max(worst, run_one(opts, size, lang))
    return worst


if __name__ == "__main__":
    sys.exit(main())
