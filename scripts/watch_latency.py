#!/usr/bin/env python3
"""Measures what a user of `mjray --watch` waits for, through the page's own /stats.json:

  start -> first image on the page (the coarse pass); then, for a save of the script while the
  first render runs and for one after the second finished: save -> new render id,
  save -> first image of the new render, save -> that render finished.

  scripts/watch_latency.py [--mjray build/mjray] SCENE.lua [mjray options...]

The scene's folder is copied to a temporary one (the copy is the one saved), so the checkout
is left alone; images go there too. Standard library only.
"""
import argparse
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import urllib.request


def status(url):
    with urllib.request.urlopen(url + "stats.json", timeout=10) as r:
        return json.load(r)


def newest_version(s):
    return max((f["version"] for f in s["frames"]), default=0)


def wait(url, predicate, timeout):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        s = status(url)
        if predicate(s):
            return time.monotonic(), s
        time.sleep(0.01)
    sys.exit("timed out; last status: " + json.dumps(s)[:400])


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--mjray", default=os.path.join(os.path.dirname(__file__), "..", "build", "mjray"))
    p.add_argument("--timeout", type=float, default=600, help="seconds to wait for each step")
    p.add_argument("scene")
    p.add_argument("options", nargs=argparse.REMAINDER)
    a = p.parse_args()

    work = tempfile.mkdtemp(prefix="mjray-watch-latency-")
    try:
        src = os.path.dirname(os.path.abspath(a.scene))
        copy = os.path.join(work, "scene")
        shutil.copytree(src, copy)
        scene = os.path.join(copy, os.path.basename(a.scene))
        log = open(os.path.join(work, "log.txt"), "w+")
        cmd = [os.path.abspath(a.mjray), "--watch", "--port", "0", "--quiet", "--outdir", work, *a.options, scene]
        start = time.monotonic()
        proc = subprocess.Popen(cmd, stdout=log, stderr=log)
        url = None
        while url is None:
            if proc.poll() is not None:
                log.seek(0)
                sys.exit("mjray ended: " + log.read())
            log.seek(0)
            m = re.search(r"at (http://\S+/)", log.read())
            url = m.group(1) if m else None
            time.sleep(0.01)
        t_url = time.monotonic()
        t_image, s = wait(url, lambda s: newest_version(s) > 0, a.timeout)
        size = "%dx%d" % (s["frames"][0]["width"], s["frames"][0]["height"])

        def save():
            """Saves the script as an editor would (a new file renamed over it), changed by a comment."""
            with open(scene) as f:
                text = f.read()
            with open(scene + ".tmp", "w") as f:
                f.write(text + "\n-- saved\n")
            os.replace(scene + ".tmp", scene)
            return time.monotonic()

        def rerender(render_id, before):
            """Times from a save to the new render's id, first image and end."""
            saved = save()
            t_id, _ = wait(url, lambda s: s["render_id"] > render_id, a.timeout)
            t_img, _ = wait(url, lambda s: s["render_id"] > render_id and newest_version(s) > before, a.timeout)
            t_end, s = wait(url, lambda s: s["render_id"] > render_id and s["state"] == "done", a.timeout)
            return t_id - saved, t_img - saved, t_end - saved, s

        # A save while the first render runs: that render must stop at once.
        mid = rerender(1, newest_version(status(url)))
        # A save once the render finished.
        after = rerender(2, newest_version(mid[3]))
        proc.send_signal(signal.SIGINT)
        code = proc.wait(timeout=60)

        print("mjray --watch %s %s (%s, %d cores)" % (" ".join(a.options), os.path.basename(a.scene), size,
                                                      os.cpu_count()))
        print("  start -> page served           %6.3f s" % (t_url - start))
        print("  start -> first image on page   %6.3f s" % (t_image - start))
        for name, (t_id, t_img, t_end, _) in (("save during the render", mid), ("save after it finished", after)):
            print("  %s:" % name)
            print("    save -> new render id         %6.3f s" % t_id)
            print("    save -> first new image       %6.3f s" % t_img)
            print("    save -> new render finished   %6.3f s" % t_end)
        print("  Ctrl-C exit code %d" % code)
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
