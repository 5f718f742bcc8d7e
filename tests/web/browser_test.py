#!/usr/bin/env python3
"""The pool page (demo/web/) in headless Chromium, driven by selenium (scripts/test.d/70-web.sh).

Serves demo/web/ on 127.0.0.1 (a free port), loads the page and checks:
  - the WebAssembly module loaded and the version string shown is the header's;
  - the pull (before the break): pressed on the aim point and pulled 60 degrees off the cue, the
    page shows the power its component along the cue gives (ccPage.pull(), #power); pulled
    forward it shows that there is no power and why, and released there it shoots nothing;
  - two shots fired through the page's own mouse handlers (press on the aim point, pull back,
    release): the break sets balls moving, and after each shot they all come to rest; the second
    is pulled 45 degrees off the cue and shoots along the aim at the speed of the pull's
    component along it;
  - no console message of level SEVERE (console.error, an uncaught exception, a failed load);
  - the aiming line (after the second shot, the mouse on the ball nearest the cue ball) is the
    cue ball's own cast with ignore= its id: it finds a ball, not the cue ball it starts in;
  - the reset button brings a new rack (after the state below is taken);
  - every resource the page loaded came from the local server;
  - determinism across targets: the page's journal (every call that changed the world) replayed
    by the native library (web_replay, tests/web/replay.c) gives the same world time, the same
    cc_world_hash and the same position and velocity of every circle, bit for bit.
Writes build/web/ (or --out): pool.png (screenshot), journal.txt, page_state.txt,
native_state.txt, figures.txt (what docs/WEB.md states of the run: scripts/doc_figures.py). usage: browser_test.py --replay PATH --version X.Y.Z [--out DIR]"""
import argparse
import functools
import math
import re
import http.server
import os
import subprocess
import sys
import threading
import time

from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.actions.action_builder import ActionBuilder

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, fmt, *args):
        pass


def serve(directory):
    handler = functools.partial(QuietHandler, directory=directory)
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


def wait_for(what, predicate, timeout):
    t0 = time.monotonic()
    while time.monotonic() - t0 < timeout:
        value = predicate()
        if value:
            return value
        time.sleep(0.05)
    raise AssertionError("timed out after %.0f s waiting for %s" % (timeout, what))


def main():
    sys.stdout.reconfigure(line_buffering=True)
    ap = argparse.ArgumentParser()
    ap.add_argument("--replay", required=True, help="the native web_replay program")
    ap.add_argument("--version", required=True, help="the version string the page must show")
    ap.add_argument("--out", default=os.path.join(ROOT, "build", "web"))
    ap.add_argument("--steps", type=int, default=4, help="world steps per animation frame")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    t_start = time.monotonic()

    server = serve(os.path.join(ROOT, "demo", "web"))
    url = "http://127.0.0.1:%d/?steps=%d" % (server.server_address[1], args.steps)
    opts = Options()
    opts.binary_location = os.environ.get("CC_CHROMIUM", "/usr/bin/chromium")
    for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
              "--window-size=1060,820", "--hide-scrollbars", "--force-device-scale-factor=1"):
        opts.add_argument(a)
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    service = Service(executable_path=os.environ.get("CC_CHROMEDRIVER", "/usr/bin/chromedriver"))
    driver = webdriver.Chrome(options=opts, service=service)
    failures = []
    try:
        driver.set_script_timeout(20)
        driver.get(url)
        wait_for("the page's module (window.ccPage)",
                 lambda: driver.execute_script("return !!window.ccPage"), 20)
        shown = driver.find_element("id", "version").text
        expected = "circlecollide %s (WebAssembly)" % args.version
        print("version shown: %r" % shown)
        if shown != expected:
            failures.append("version string %r, expected %r" % (shown, expected))

        def client(x, y):
            return driver.execute_script("return ccPage.clientPoint(arguments[0], arguments[1])", x, y)

        def nearest_ball():
            """the table point of the object ball nearest the cue ball"""
            return driver.execute_script("""
                const cue = ccPage.balls().find(b => b.id === ccPage.cueId());
                const others = ccPage.balls().filter(b => b.id !== ccPage.cueId());
                others.sort((a, b) => Math.hypot(a.x - cue.x, a.y - cue.y) - Math.hypot(b.x - cue.x, b.y - cue.y));
                return [others[0].x, others[0].y];""")

        def aim_axis(aim):
            """the unit vector from the cue ball to the aim point, and its left normal"""
            cue = driver.execute_script("return ccPage.balls().find(b => b.id === ccPage.cueId())")
            d = math.hypot(aim[0] - cue["x"], aim[1] - cue["y"])
            u = ((aim[0] - cue["x"]) / d, (aim[1] - cue["y"]) / d)
            return u, (-u[1], u[0])

        def press_and_pull(aim, back, side):
            """press on the aim point, then move `back` metres against the aim and `side` across
            it in five moves, the button held (the pull is read before it is released)"""
            u, n = aim_axis(aim)
            p0 = client(*aim)
            p1 = client(aim[0] - back * u[0] + side * n[0], aim[1] - back * u[1] + side * n[1])
            actions = ActionBuilder(driver)
            actions.pointer_action.move_to_location(round(p0["x"]), round(p0["y"]))
            actions.pointer_action.pointer_down()
            for k in range(1, 6):
                actions.pointer_action.move_to_location(round(p0["x"] + (p1["x"] - p0["x"]) * k / 5),
                                                        round(p0["y"] + (p1["y"] - p0["y"]) * k / 5))
            actions.perform()
            time.sleep(0.1)  # a frame, so that #power shows this pull
            return u

        def release():
            actions = ActionBuilder(driver)
            actions.pointer_action.pointer_up()
            actions.perform()

        def check_pull_shown(what, q, want_back, text):
            """the pull's component against the aim is what the mouse did (to a pixel, 3 mm), its
            speed MAX_SPEED * component / MAX_PULL (9 m/s for 0.45 m), and #power says it"""
            speed = 9.0 * min(max(q["back"], 0.0), 0.45) / 0.45
            if abs(q["back"] - want_back) > 0.006 or abs(q["speed"] - speed) > 1e-9:
                failures.append("%s: pull %r, want a component of %.3f m and %.3f m/s" % (what, q, want_back, speed))
            shown = re.search(r"power ([0-9.]+) m/s", text)
            if not shown or abs(float(shown.group(1)) - q["speed"]) > 0.051:
                failures.append("%s: #power says %r while the pull gives %.2f m/s" % (what, text, q["speed"]))
            print("%s: component %.3f m against the aim, %.2f m/s; #power: %s" % (what, q["back"], q["speed"], text))

        def check_pull():
            """pulled 60 degrees off the cue (0.2 m back, 0.3464 m across: 0.4 m in all), the
            page shows the power of the 0.2 m along the cue, 9 * 0.2 / 0.45 = 4.0 m/s, and says
            the pull is off the cue; pushed forward (0.1 m toward the aim) it shows no power and
            why; released there, no shot, and the page says why"""
            aim = (0.75 * 2.54, 0.5 * 1.27)
            press_and_pull(aim, 0.2, 0.2 * math.tan(math.radians(60)))
            q, text = driver.execute_script("return [ccPage.pull(), ccPage.powerText()]")
            check_pull_shown("pull 60 degrees off the cue", q, 0.2, text)
            if "off the cue" not in text:
                failures.append("a pull 60 degrees off the cue: #power does not say so: %r" % text)
            p = client(aim[0] + 0.1 * aim_axis(aim)[0][0], aim[1] + 0.1 * aim_axis(aim)[0][1])
            actions = ActionBuilder(driver)
            actions.pointer_action.move_to_location(round(p["x"]), round(p["y"]))
            actions.perform()
            time.sleep(0.1)
            q, text = driver.execute_script("return [ccPage.pull(), ccPage.powerText()]")
            print("pull forward: component %.3f m; #power: %s" % (q["back"], text))
            if not (q["back"] < 0 and q["speed"] == 0 and "power 0 m/s: pull back along the cue" in text):
                failures.append("a pull toward the aim: %r, #power %r" % (q, text))
            release()
            time.sleep(0.1)
            state, shots, text = driver.execute_script("return [ccPage.state(), ccPage.shots(), ccPage.powerText()]")
            print("released there: state %s, shots %d; #power: %s" % (state, shots, text))
            if state != "aim" or shots != 0 or "no shot: pull back along the cue" not in text:
                failures.append("a release without power: state %s, %d shots, #power %r" % (state, shots, text))

        def shoot(aim, pull, number, side=0.0):
            """the page's own mouse handlers: press on the aim point, pull back `pull` metres
            along the aim (and `side` across it) in five moves, release; then wait until every
            ball rests. The shot goes along the aim at the speed the pull showed before release."""
            press_and_pull(aim, pull, side)
            q = driver.execute_script("return ccPage.pull()")
            if side:
                check_pull_shown("shot %d, pulled %.0f degrees off the cue" % (number, math.degrees(math.atan2(side, pull))),
                                 q, pull, driver.execute_script("return ccPage.powerText()"))
            release()
            wait_for("shot %d (ccPage.shots() == %d)" % (number, number),
                     lambda: driver.execute_script("return ccPage.shots()") == number, 5)
            shot = driver.execute_script("return ccPage.lastShot()")
            if abs(shot["speed"] - q["speed"]) > 1e-12 or abs(shot["x"] - q["aim"]["x"]) > 1e-12 or \
                    abs(shot["y"] - q["aim"]["y"]) > 1e-12:
                failures.append("shot %d: %r, the pull before release %r" % (number, shot, q))
            t_shot = time.monotonic()
            wait_for("every ball at rest after shot %d" % number, lambda: driver.execute_script(
                "return ccPage.state() === 'aim' && ccPage.shots() === arguments[0]", number), 40)
            print("shot %d: balls at rest at %.1f s of world time (%.1f s in the browser, %d steps in all); "
                  "potted: %s" % (number, driver.execute_script("return ccPage.time()"), time.monotonic() - t_shot,
                                  driver.execute_script("return ccPage.steps()"),
                                  driver.execute_script("return ccPage.potted()")))

        def check_rest(what):
            rolling = [b["id"] for b in driver.execute_script("return ccPage.balls()") if b["vx"] != 0 or b["vy"] != 0]
            if rolling:
                failures.append("%s: balls still moving: %s" % (what, rolling))

        check_pull()
        before = {b["id"]: b for b in driver.execute_script("return ccPage.balls()")}
        # the break: aimed at the apex ball, pulled back 0.4 m (0.4 / 0.45 of full power: 8 m/s,
        # the demo's break)
        shoot((0.75 * 2.54, 0.5 * 1.27), 0.4, 1)
        after = {b["id"]: b for b in driver.execute_script("return ccPage.balls()")}
        moved = sum(1 for i, b in before.items()
                    if i not in after or (after[i]["x"], after[i]["y"]) != (b["x"], b["y"]))
        print("balls moved (or potted) by the break: %d of %d" % (moved, len(before)))
        if moved < 8:
            failures.append("only %d balls moved" % moved)
        check_rest("after the break")
        # a second shot, at the ball nearest the cue ball, pulled 45 degrees off the cue: 0.25 m
        # along it, 9 * 0.25 / 0.45 = 5 m/s
        shoot(nearest_ball(), 0.25, 2, side=0.25)
        check_rest("after the second shot")
        # the mouse on the nearest ball again, so that the screenshot shows the next aim: the
        # aiming line, the ghost ball and the object ball's path
        target = client(*nearest_ball())
        move = ActionBuilder(driver)
        move.pointer_action.move_to_location(round(target["x"]), round(target["y"]))
        move.perform()
        time.sleep(0.2)

        # the aiming line is the cue ball's own cast, which its filter's ignore= leaves out: it
        # finds the ball aimed at, not the cue ball it starts inside (an overlap at t = 0)
        aim_hit, cue_id = driver.execute_script("return [ccPage.aimHit(), ccPage.cueId()]")
        if not aim_hit or aim_hit["circle"] < 0 or aim_hit["circle"] == cue_id or aim_hit["overlap"]:
            failures.append("the aiming cast found %r (the cue ball is %d): not the ball aimed at" % (aim_hit, cue_id))
        else:
            print("aiming cast: ball %d at t = %.3f of the line (the cue ball %d left out by ignore=)"
                  % (aim_hit["circle"], aim_hit["t"], cue_id))
        driver.save_screenshot(os.path.join(args.out, "pool.png"))
        journal = driver.execute_script("return ccPage.journal()")
        page_state = driver.execute_script("return ccPage.worldState()")
        run_figures = driver.execute_script(
            "return {steps: ccPage.steps(), time: ccPage.time(), potted: ccPage.potted().length, fouls: ccPage.fouls(), "
            "bytes: ccPage.worldBytes()}")
        chromium = driver.capabilities.get("browserVersion", "0").split(".")[0]
        # the reset button: a new rack in the same memory, nothing potted, the cue ball back
        driver.find_element("id", "reset").click()
        wait_for("the reset", lambda: driver.execute_script(
            "return ccPage.shots() === 0 && ccPage.potted().length === 0 && ccPage.balls().length === 16"), 5)
        print("reset: a new rack of 15 and the cue ball")
        # nothing fetched from elsewhere: every resource the page loaded came from our server
        origin = "http://127.0.0.1:%d/" % server.server_address[1]
        loaded = driver.execute_script("return performance.getEntriesByType('resource').map(e => e.name)")
        foreign = [u for u in loaded if not u.startswith(origin)]
        print("resources loaded: %s" % ", ".join(sorted(u[len(origin):] for u in loaded if u.startswith(origin))))
        if foreign:
            failures.append("fetched from elsewhere: %s" % foreign)
        severe = [e for e in driver.get_log("browser") if e.get("level") == "SEVERE"]
        for e in severe:
            failures.append("console: %s" % e.get("message"))
    finally:
        driver.quit()
        server.shutdown()

    with open(os.path.join(args.out, "journal.txt"), "w") as f:
        f.write(journal)
    with open(os.path.join(args.out, "page_state.txt"), "w") as f:
        f.write(page_state)
    run = subprocess.run([args.replay, os.path.join(args.out, "journal.txt")], capture_output=True, text=True)
    sys.stderr.write(run.stderr)
    with open(os.path.join(args.out, "native_state.txt"), "w") as f:
        f.write(run.stdout)
    if run.returncode != 0:
        failures.append("web_replay exited with %d" % run.returncode)
    page_lines, native_lines = page_state.splitlines(), run.stdout.splitlines()
    differ = [(a, b) for a, b in zip(page_lines, native_lines) if a != b]
    if len(page_lines) != len(native_lines) or differ or not page_lines:
        failures.append("the native replay differs from the page: %d lines against %d, %d differ"
                        % (len(native_lines), len(page_lines), len(differ)))
        for a, b in differ[:5]:
            print("  page:   " + a + "\n  native: " + b)
    else:
        print("determinism: the native replay of the %d journal lines matches the page bit for bit "
              "(world time, hash, position and velocity of %d circles): %s"
              % (len(journal.splitlines()), len(page_lines) - 2, page_lines[1]))
    # what docs/WEB.md states of this run (scripts/doc_figures.py checks it against the text)
    with open(os.path.join(args.out, "figures.txt"), "w") as f:
        f.write("web.steps %d\nweb.world_time %.1f\nweb.potted %d\nweb.cue_potted %d\nweb.journal_lines %d\n"
                "web.hash %s\nweb.circles %d\nweb.chromium %s\nweb.world_bytes %d\n"
                % (run_figures["steps"], run_figures["time"], run_figures["potted"], run_figures["fouls"],
                   len(journal.splitlines()), page_lines[1].split()[-1] if len(page_lines) > 1 else "?",
                   len(page_lines) - 2, chromium, run_figures["bytes"]))
    print("browser test: %.1f s; screenshot %s" % (time.monotonic() - t_start, os.path.join(args.out, "pool.png")))
    for f in failures:
        print("FAILED: " + f)
    print("PASSED" if not failures else "FAILED")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
