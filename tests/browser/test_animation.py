#!/usr/bin/python3
"""The page of `rollkin solve --animate` in a real browser (Debian's chromium, headless, driven by selenium
through chromium-driver).

  usage: /usr/bin/python3 test_animation.py PATH/TO/rollkin SOURCE_DIR

Every page is written in the same run as a CSV of the same solve (--animate and --csv together), and the CSV
is the independent truth: the input value the page shows and the transforms it gives the link groups at a pose
must be that pose's row (input column; <link>.x, <link>.y, <link>.angle to the 7 significant digits the page
stores). Also checked: the page is one file under 1 MB that loads nothing (no URL, no src/href, and the
browser's resource timing is empty), the slider moves the links, play advances the poses and pause stops
them, a long sweep is shown in a bounded number of frames that are each their CSV row and include both rows of
every status change, unsolved poses show their status with the moving links hidden, names with markup and control characters
neither break the page nor run script, and the browser log has no SEVERE entry (JavaScript errors).
Prints one line per check and "N passed, M failed" last; exit status 1 when a check fails.
"""
import csv
import math
import os
import re
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

from selenium import webdriver
from selenium.common.exceptions import NoAlertPresentException
from selenium.webdriver.chrome.service import Service

BIN, SRC = (os.path.abspath(a) for a in sys.argv[1:3])
EXAMPLE = os.path.join(SRC, "examples", "paper_fourbar.json")
results = {"passed": 0, "failed": 0}


def check(name, ok, detail=""):
    results["passed" if ok else "failed"] += 1
    print(("ok   " if ok else "FAIL ") + name + ("" if ok or not detail else ": " + detail))


def solve(scene, html, table, *extra):
    """One run of rollkin writing the page and the CSV of the same solve."""
    run = subprocess.run([BIN, "solve", scene, "--animate", html, "--csv", table, *extra], capture_output=True, text=True)
    return run.returncode, list(csv.DictReader(open(table, newline=""))) if os.path.exists(table) else []


def browser():
    opts = webdriver.ChromeOptions()
    opts.binary_location = "/usr/bin/chromium"
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--window-size=1000,800"):
        opts.add_argument(arg)
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=opts)


# JavaScript run in the page: move the slider to each pose (value + input event, as a user's drag does) and
# read what the page shows: the input value, the status, each link group's transform and visibility.
READ_POSES = """
var slider = document.getElementById("pose"), out = [];
for (var k of arguments[0]) {
  slider.value = String(k);
  slider.dispatchEvent(new Event("input", {bubbles: true}));
  var links = [];
  for (var g of document.querySelectorAll("g.link"))
    links.push({name: g.querySelector("title").textContent, transform: g.getAttribute("transform"),
                visibility: g.getAttribute("visibility") || "visible"});
  var contacts = Array.from(document.querySelectorAll("circle.contact"), c => c.getAttribute("transform"));
  out.push({pose: k, value: document.getElementById("input-value").textContent, contacts: contacts,
            index: document.getElementById("pose-index").textContent,
            status: document.getElementById("status").textContent, links: links});
}
return out;
"""

# The same without moving the slider: what the page shows now.
READ_NOW = READ_POSES.replace("for (var k of arguments[0]) {", "for (var k of [Number(slider.value)]) {").replace(
    'slider.dispatchEvent(new Event("input", {bubbles: true}));', "").replace("return out;", "return out[0];")

TRANSFORM = re.compile(r"^translate\(([^ ]+) ([^ )]+)\) rotate\(([^ )]+)\)$")


def close(stored, truth):
    """A value stored with 7 significant digits against the CSV's full-precision one."""
    return abs(stored - truth) <= 1e-6 * abs(truth) + 1e-300


def transform_errors(seen, row):
    """Where a pose's link transforms differ from the CSV row's link columns (empty when they agree)."""
    bad = []
    for link in seen["links"]:
        m = TRANSFORM.match(link["transform"] or "")
        if not m:
            bad.append("%s: transform %r" % (link["name"], link["transform"]))
            continue
        for got, column in zip(m.groups(), (".x", ".y", ".angle")):
            truth = float(row[link["name"] + column])
            if not close(float(got), truth):
                bad.append("%s%s: page %s, CSV %r" % (link["name"], column, got, truth))
    return bad


def severe_log(driver):
    return [e["message"] for e in driver.get_log("browser") if e["level"] == "SEVERE"]


def main():
    work = tempfile.mkdtemp(prefix="rollkin_browser.")
    os.chdir(work)

    # ---- the paper's example: file, size, nothing external ----------------------------------------------
    rc, rows = solve(EXAMPLE, "anim.html", "anim.csv")
    check("solve --animate --csv exits 0 with 151 rows", rc == 0 and len(rows) == 151, "exit %d, %d rows" % (rc, len(rows)))
    text = open("anim.html", encoding="utf-8").read()
    size = os.path.getsize("anim.html")
    print("     page size %d bytes" % size)
    check("page under 1 MB", size < 1_000_000, "%d bytes" % size)
    external = re.findall(r"https?:|ftp:|file:|\bsrc\s*=|\bhref\s*=|url\(|@import|<link\b|<iframe\b|<img\b", text, re.I)
    check("no external reference (no URL, src=, href=, url(), @import, <link>)", not external, str(external[:5]))
    try:
        ET.fromstring(text.split("\n", 1)[1])  # after <!DOCTYPE html>
        well_formed = True
    except ET.ParseError as e:
        well_formed = str(e)
    check("page is well-formed XML", well_formed is True, str(well_formed))

    driver = browser()
    try:
        driver.get("file://" + os.path.abspath("anim.html"))
        resources = driver.execute_script("return performance.getEntriesByType('resource').map(e => e.name);")
        check("the browser loaded no resource besides the page", resources == [], str(resources))
        check("a play button and a range slider over the 151 poses",
              driver.execute_script("var s = document.getElementById('pose'); return [document.querySelector('button#play') !== null,"
                                    " s.type, s.min, s.max];") == [True, "range", "0", "150"])
        first = driver.execute_script(READ_NOW)
        check("the page opens at the first pose", first["pose"] == 0 and first["value"] == "-50", str(first["value"]))

        # ---- every pose through the slider against the CSV -------------------------------------------------
        seen = driver.execute_script(READ_POSES, list(range(len(rows))))
        value_bad = [s["pose"] for s in seen if float(s["value"]) != float(rows[s["pose"]]["O_A.theta2"])
                     or s["index"] != str(s["pose"] + 1)]
        check("the input value shown equals the CSV's input column at every pose", not value_bad and len(seen) == 151,
              "poses %s" % value_bad[:5])
        errors = [(s["pose"], e) for s in seen for e in transform_errors(s, rows[s["pose"]])]
        check("link transforms equal the CSV's <link>.x, .y, .angle at every pose (7 digits)", not errors, str(errors[:3]))
        # The contact points against the geometry (examples/paper_fourbar.json): A lies on link3's rim (radius 1
        # about link3's origin), B on link3's rim and on link4's (radius 4 about (2, 0) in link4's frame), with
        # the link poses of the CSV.
        def contact_errors(s, row):
            pts = [tuple(map(float, re.match(r"^translate\(([^ ]+) ([^ )]+)\)$", t).groups())) for t in s["contacts"]]
            l3 = (float(row["link3.x"]), float(row["link3.y"]))
            a4 = math.radians(float(row["link4.angle"]))
            c4 = (float(row["link4.x"]) + 2 * math.cos(a4), float(row["link4.y"]) + 2 * math.sin(a4))
            d = [math.dist(pts[0], l3) - 1, math.dist(pts[1], l3) - 1, math.dist(pts[1], c4) - 4]
            return [x for x in d if abs(x) > 1e-5]  # 7 digits of coordinates up to 10
        errors = [(s["pose"], contact_errors(s, rows[s["pose"]])) for s in seen if contact_errors(s, rows[s["pose"]])]
        check("contact points: A on link3's rim, B on link3's and link4's rims at every pose (1e-5)",
              not errors and all(len(s["contacts"]) == 2 for s in seen), str(errors[:3]))
        check("four link groups named as the CSV's links", [l["name"] for l in seen[0]["links"]] == ["link1", "link2", "link3", "link4"])
        moved = [l["name"] for l, l0 in zip(seen[100]["links"], first["links"]) if l["transform"] != l0["transform"]]
        check("moving the slider to pose 100 changes the moving links' transforms", moved == ["link2", "link3", "link4"], str(moved))
        check("every status shown is ok", all(s["status"] == "ok" for s in seen))

        # ---- play and pause -------------------------------------------------------------------------------------
        driver.execute_script(READ_POSES, [10])
        driver.find_element("id", "play").click()
        time.sleep(0.5)
        playing = driver.execute_script(READ_NOW)
        check("play: after 0.5 s the poses have advanced and the button says Pause",
              playing["pose"] > 10 and driver.find_element("id", "play").text == "Pause", "pose %d" % playing["pose"])
        driver.find_element("id", "play").click()
        stopped = driver.execute_script(READ_NOW)
        time.sleep(0.3)
        later = driver.execute_script(READ_NOW)
        check("pause: the poses stop advancing and the button says Play",
              stopped == later and driver.find_element("id", "play").text == "Play", "%d then %d" % (stopped["pose"], later["pose"]))
        check("after playing, the pose shown is the CSV row of the slider's position",
              not transform_errors(stopped, rows[stopped["pose"]]) and
              float(stopped["value"]) == float(rows[stopped["pose"]]["O_A.theta2"]), str(transform_errors(stopped, rows[stopped["pose"]])))
        check("no SEVERE entry in the browser log (paper example)", not severe_log(driver), str(severe_log(driver)))

        # ---- beyond the motion limits: unsolved poses are shown as such ----------------------------------------
        rc, wide = solve(EXAMPLE, "wide.html", "wide.csv", "--from", "-70", "--to", "120")
        unsolved = [k for k, r in enumerate(wide) if r["status"] != "ok"]
        solved = [k for k, r in enumerate(wide) if r["status"] == "ok"]
        check("wide sweep: exit 1, rows both solved and not", rc == 1 and unsolved and solved)
        driver.get("file://" + os.path.abspath("wide.html"))
        seen = driver.execute_script(READ_POSES, unsolved + solved)
        bad = []
        for s in seen:
            row = wide[s["pose"]]
            hidden = {l["name"]: l["visibility"] == "hidden" for l in s["links"]}
            if float(s["value"]) != float(row["O_A.theta2"]) or not s["status"].startswith(row["status"]):
                bad.append((s["pose"], s["value"], s["status"]))
            elif row["status"] != "ok" and hidden != {"link1": False, "link2": True, "link3": True, "link4": True}:
                bad.append((s["pose"], "links not hidden", hidden))
            elif row["status"] == "ok" and (any(hidden.values()) or transform_errors(s, row)):
                bad.append((s["pose"], "solved pose", hidden, transform_errors(s, row)))
        check("wide sweep: unsolved poses show their CSV status with the moving links hidden, solved ones the CSV's poses",
              not bad, str(bad[:3]))
        contacts_hidden = driver.execute_script(READ_POSES.replace("return out;", "") +
                                                "return document.getElementById('contact-0').getAttribute('visibility');",
                                                [unsolved[0]])
        check("wide sweep: the contact points are hidden at an unsolved pose", contacts_hidden == "hidden")
        check("no SEVERE entry in the browser log (wide sweep)", not severe_log(driver), str(severe_log(driver)))

        # ---- a long sweep: bounded frames, evenly spaced, both sides of every status change -------------------
        # 19,001 poses beyond the motion limits: the page shows 2000 evenly spaced poses and the poses on both
        # sides of each status change (docs/reliability.md, "Outputs at any size"); every frame is its CSV row.
        rc, fine = solve(EXAMPLE, "fine.html", "fine.csv", "--from", "-70", "--to", "120", "--step", "0.01")
        size = os.path.getsize("fine.html")
        print("     page size %d bytes for %d poses" % (size, len(fine)))
        check("long sweep: exit 1, 19001 rows, page under 1 MB", rc == 1 and len(fine) == 19001 and size < 1_000_000,
              "exit %d, %d rows, %d bytes" % (rc, len(fine), size))
        driver.get("file://" + os.path.abspath("fine.html"))
        frames = int(driver.execute_script("return document.getElementById('pose').max;")) + 1
        changes = [k for k in range(1, len(fine)) if fine[k]["status"] != fine[k - 1]["status"]]
        check("long sweep: between 2000 and 2000 + 2 x changes frames", 2000 <= frames <= 2000 + 2 * len(changes) < len(fine),
              "%d frames, %d changes" % (frames, len(changes)))
        seen = driver.execute_script(READ_POSES, list(range(frames)))
        shown = [int(s["index"]) - 1 for s in seen]
        bad = []
        for s, row in zip(seen, shown):
            truth = fine[row]
            if float(s["value"]) != float(truth["O_A.theta2"]) or not s["status"].startswith(truth["status"]):
                bad.append((row, s["value"], s["status"]))
            elif truth["status"] == "ok" and transform_errors(s, truth):
                bad.append((row, transform_errors(s, truth)))
        check("long sweep: every frame shows its CSV row (input, status, link transforms)", not bad, str(bad[:3]))
        spacing = math.ceil((len(fine) - 1) / 1999)
        check("long sweep: frames in row order from the first to the last row, no gap above (n - 1) / 1999 rows",
              shown == sorted(set(shown)) and shown[0] == 0 and shown[-1] == len(fine) - 1 and
              max(b - a for a, b in zip(shown, shown[1:])) <= spacing, "largest gap %d" % max(b - a for a, b in zip(shown, shown[1:])))
        missing = [k for k in changes if k - 1 not in shown or k not in shown]
        check("long sweep: both rows of every status change are frames (%d changes)" % len(changes), changes and not missing,
              str(missing[:5]))
        check("long sweep: the title says how many poses and frames",
              "19001 poses of the sweep of " in driver.find_element("tag name", "h1").text and
              driver.find_element("tag name", "h1").text.endswith(", %d of them shown (evenly spaced, and both sides of "
                                                                  "every status change)" % frames),
              driver.find_element("tag name", "h1").text)
        check("no SEVERE entry in the browser log (long sweep)", not severe_log(driver), str(severe_log(driver)))

        # ---- singular poses (the anti-parallelogram's folded poses): shown with their values, marked singular ---
        rc, anti = solve(os.path.join(SRC, "examples", "antiparallelogram.json"), "anti.html", "anti.csv")
        singular = [k for k, r in enumerate(anti) if r["status"] == "singular"]
        driver.get("file://" + os.path.abspath("anti.html"))
        seen = driver.execute_script(READ_POSES, singular)
        bad = [(s["pose"], s["status"], transform_errors(s, anti[s["pose"]])) for s in seen
               if not s["status"].startswith("singular: the values follow the branch") or transform_errors(s, anti[s["pose"]])
               or any(l["visibility"] == "hidden" for l in s["links"])]
        check("singular poses: the CSV's values shown, links visible, status says singular", singular and not bad, str(bad[:2]))
        check("no SEVERE entry in the browser log (singular poses)", not severe_log(driver), str(severe_log(driver)))

        # ---- names with markup, script and control characters ---------------------------------------------------
        scene = open(EXAMPLE, encoding="utf-8").read()
        evil = 'li\\u0001nk</script><script>injected=1</script>\\"2'  # JSON text: \u0001 and \" escapes
        scene = scene.replace("link2", evil).replace("O_A", "O\\u0007_A<b>")
        open("evil.json", "w", encoding="utf-8").write(scene)
        rc, evil_rows = solve("evil.json", "evil.html", "evil.csv", "--from", "0", "--to", "10", "--step", "5")
        check("names with markup and control characters: exit 0", rc == 0 and os.path.exists("evil.html"), "exit %d" % rc)
        if not os.path.exists("evil.html"):
            raise SystemExit("%d passed, %d failed" % (results["passed"], results["failed"]))
        try:
            ET.fromstring(open("evil.html", encoding="utf-8").read().split("\n", 1)[1])
            well_formed = True
        except ET.ParseError as e:
            well_formed = str(e)
        check("names with markup and control characters: page is well-formed XML", well_formed is True, str(well_formed))
        driver.get("file://" + os.path.abspath("evil.html"))
        try:
            driver.switch_to.alert
            alert = True
        except NoAlertPresentException:
            alert = False
        injected = driver.execute_script("return typeof window.injected;")
        names = driver.execute_script("return Array.from(document.querySelectorAll('g.link > title'), t => t.textContent);")
        check("names cannot inject script: window.injected undefined, no alert", injected == "undefined" and not alert, injected)
        check("names shown with control characters escaped visibly",
              names[1] == 'li\\x01nk</script><script>injected=1</script>"2', repr(names))
        shown = driver.execute_script(READ_POSES, [2])[0]
        check("names with markup: the page still plays (input 10 at pose 2)", float(shown["value"]) == 10.0, shown["value"])
        check("no SEVERE entry in the browser log (names)", not severe_log(driver), str(severe_log(driver)))
    finally:
        driver.quit()

    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
