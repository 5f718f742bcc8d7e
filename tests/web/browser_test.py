#!/usr/bin/env python3
"""The pool page (demo/web/) in headless Chromium, driven by selenium (scripts/test.d/70-web.sh).

Serves demo/web/ on 127.0.0.1 (a free port), loads the page and checks:
  - the WebAssembly module loaded and the version string shown is the header's;
  - two shots fired through the page's own mouse handlers (press on the aim point, pull back,
    release): the break sets balls moving, and after each shot they all come to rest;
  - no console message of level SEVERE (console.error, an uncaught exception, a failed load);
  - the reset button brings a new rack (after the state below is taken);
  - every resource the page loaded came from the local server;
  - determinism across targets: the page's journal (every call that changed the world) replayed
    by the native library (web_replay, tests/web/replay.c) gives the same world time, the same
    cc_world_hash and the same position and velocity of every circle, bit for bit.
Writes build/web/ (or --out): pool.png (screenshot), journal.txt, page_state.txt,
native_state.txt. usage: browser_test.py --replay PATH --version X.Y.Z [--out DIR]"""
import argparse
import functools
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

        def shoot(aim, pull, number):
            """the page's own mouse handlers: press on the aim point, pull back `pull` metres
            along the aim in five moves, release; then wait until every ball rests"""
            cue = driver.execute_script("return ccPage.balls().find(b => b.id === ccPage.cueId())")
            d = ((aim[0] - cue["x"]) ** 2 + (aim[1] - cue["y"]) ** 2) ** 0.5
            u = ((aim[0] - cue["x"]) / d, (aim[1] - cue["y"]) / d)
            p0, p1 = client(*aim), client(aim[0] - pull * u[0], aim[1] - pull * u[1])
            actions = ActionBuilder(driver)
            actions.pointer_action.move_to_location(round(p0["x"]), round(p0["y"]))
            actions.pointer_action.pointer_down()
            for k in range(1, 6):
                actions.pointer_action.move_to_location(round(p0["x"] + (p1["x"] - p0["x"]) * k / 5),
                                                        round(p0["y"] + (p1["y"] - p0["y"]) * k / 5))
            actions.pointer_action.pointer_up()
            actions.perform()
            wait_for("shot %d (ccPage.shots() == %d)" % (number, number),
                     lambda: driver.execute_script("return ccPage.shots()") == number, 5)
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
        # a second shot, at the ball nearest the cue ball (5 m/s)
        shoot(nearest_ball(), 0.25, 2)
        check_rest("after the second shot")
        # the mouse on the nearest ball again, so that the screenshot shows the next aim: the
        # aiming line, the ghost ball and the object ball's path
        target = client(*nearest_ball())
        move = ActionBuilder(driver)
        move.pointer_action.move_to_location(round(target["x"]), round(target["y"]))
        move.perform()
        time.sleep(0.2)

        driver.save_screenshot(os.path.join(args.out, "pool.png"))
        journal = driver.execute_script("return ccPage.journal()")
        page_state = driver.execute_script("return ccPage.worldState()")
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
    print("browser test: %.1f s; screenshot %s" % (time.monotonic() - t_start, os.path.join(args.out, "pool.png")))
    for f in failures:
        print("FAILED: " + f)
    print("PASSED" if not failures else "FAILED")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
