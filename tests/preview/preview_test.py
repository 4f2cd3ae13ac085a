#!/usr/bin/env python3
"""facet preview under Xvfb (docs/preview.md): the window shows facet's own
render, reloads an edited scene, shows a broken scene's error over the last
image without closing, and its keys write snapshots and print cameras that
`facet render` reproduces bit for bit.

    preview_test.py FACET    (exit 77: skipped, Xvfb, xdotool or xwd missing)
"""
import os
import re
import select
import shutil
import subprocess
import sys
import tempfile
import threading
import time

import numpy as np
import yaml
from skimage import io as skio

FACET = os.path.abspath(sys.argv[1])
WAIT = 120  # seconds for any one thing to happen (sanitizer builds are slow)
WIDTH, HEIGHT = 320, 240


def scene_text(color, camera=None, broken=False):
    camera = camera or "camera:\n  position: [0, 1.5, 4]\n  target: [0, 0.3, 0]\n"
    material = "colour" if broken else "color"  # a misspelt key: an error at its line
    return f"""style: look.yaml
output:
  size: [{WIDTH}, {HEIGHT}]
  frames: 1-12
  fps: 4
  samples: 4
{camera}objects:
  - primitive: cube
    rotate: {{ keys: {{ 1: [0, 0, 0], 12: [0, 90, 0] }} }}
    material: {{ {material}: {color} }}
  - primitive: plane
    scale: [4, 1, 4]
    translate: [0, -0.5, 0]
  - mesh: meshes/sail.obj
    translate: [1.2, 0, 0]
    material: {{ color: [0.9, 0.8, 0.2], double_sided: true }}
"""


def sail_obj(height):
    """A triangle standing on the floor: an asset whose edit must reload."""
    return f"v 0 -0.5 0\nv 0.8 -0.5 0\nv 0 {height} 0\nf 1 2 3\n"


def write_atomically(path, text):
    # As editors do: a new file renamed over the old one.
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def read_xwd(data):
    """An X window dump (XWD, version 7) of a 24/32-bit TrueColor window as RGB."""
    header = np.frombuffer(data[:100], dtype=">u4")
    header_size, version, _, depth, width, height = header[:6]
    byte_order, bits_per_pixel, bytes_per_line = header[7], header[11], header[12]
    masks = header[14:17]
    colormap_entries = header[19]
    assert version == 7 and bits_per_pixel == 32, f"unexpected XWD: depth {depth}, {bits_per_pixel} bpp"
    start = int(header_size) + 12 * int(colormap_entries)
    rows = np.frombuffer(data[start:start + int(bytes_per_line) * int(height)],
                         dtype="<u4" if byte_order == 0 else ">u4")
    pixels = rows.reshape(int(height), int(bytes_per_line) // 4)[:, :int(width)]
    channels = []
    for mask in masks:
        shift = (int(mask) & -int(mask)).bit_length() - 1
        channels.append((pixels & int(mask)) >> shift)
    return np.stack(channels, axis=-1).astype(np.uint8)


class Preview:
    """A running `facet preview`, its stderr lines collected as they come."""

    def __init__(self, args, cwd, env):
        self.process = subprocess.Popen([FACET, "preview", *args], cwd=cwd, env=env,
                                        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.lines, self.stdout = [], []
        self.lock = threading.Lock()
        threading.Thread(target=self._read, args=(self.process.stderr, self.lines), daemon=True).start()
        threading.Thread(target=self._read, args=(self.process.stdout, self.stdout), daemon=True).start()

    def _read(self, stream, into):
        for line in stream:
            with self.lock:
                into.append(line.rstrip("\n"))

    def wait_for(self, pattern, after=0, into=None):
        """The first line from index `after` on matching `pattern`, and its index."""
        into = self.lines if into is None else into
        deadline = time.time() + WAIT
        while time.time() < deadline:
            with self.lock:
                for i in range(after, len(into)):
                    if re.search(pattern, into[i]):
                        return into[i], i
            assert self.process.poll() is None, f"preview exited ({self.process.returncode}):\n" + "\n".join(self.lines)
            time.sleep(0.05)
        raise AssertionError(f"no line matching {pattern!r} within {WAIT} s; stderr:\n" + "\n".join(self.lines))

    def count(self):
        with self.lock:
            return len(self.lines)


def render(cwd, out, frame=1):
    subprocess.run([FACET, "render", "scene.yaml", "-f", str(frame), "-o", out, "-q", "--overwrite"],
                   cwd=cwd, check=True, timeout=WAIT)
    return os.path.join(cwd, out, "scene", f"color.{frame:04}.png")


def main():
    missing = [tool for tool in ("Xvfb", "xdotool", "xwd") if not shutil.which(tool)]
    if missing:
        print("SKIP: " + ", ".join(missing) + " not installed (scripts/setup.sh --tests installs them)")
        return 77
    work = tempfile.mkdtemp(prefix="facet-preview-")
    read_fd, write_fd = os.pipe()
    xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(write_fd), "-screen", "0", "1280x1024x24",
                             "-nolisten", "tcp"], pass_fds=(write_fd,), stderr=subprocess.DEVNULL)
    os.close(write_fd)
    ready, _, _ = select.select([read_fd], [], [], 30)
    assert ready, "Xvfb did not start"
    display = ":" + os.read(read_fd, 16).decode().strip()
    env = dict(os.environ, DISPLAY=display)
    # Sanitizer builds: Mesa's OpenGL driver, loaded and unloaded at run
    # time, and D-Bus leave allocations that LeakSanitizer cannot name or
    # that are not facet's. The preview's own code is leak-checked in
    # facet_tests (test_preview.cpp); here the other sanitizers stay on.
    env["ASAN_OPTIONS"] = ":".join(filter(None, [os.environ.get("ASAN_OPTIONS"), "detect_leaks=0"]))
    passed = False
    try:
        run_checks(work, env)
        passed = True
    finally:
        xvfb.terminate()
        xvfb.wait()
        if passed:
            shutil.rmtree(work, ignore_errors=True)
        else:
            print(f"kept {work} (the scene, renders and last screenshot) for a look")
    print("preview: all checks passed")
    return 0


def screenshot(window, env, keep_as=None):
    """The window's pixels; FACET_PREVIEW_SHOTS=DIR also keeps them as DIR/NAME.png."""
    dump = subprocess.run(["xwd", "-silent", "-id", window], env=env, check=True, capture_output=True,
                          timeout=WAIT).stdout
    shot = read_xwd(dump)
    if keep_as and os.environ.get("FACET_PREVIEW_SHOTS"):
        skio.imsave(os.path.join(os.environ["FACET_PREVIEW_SHOTS"], keep_as + ".png"), shot,
                    check_contrast=False)
    return shot


def image_area(shot):
    return shot[:HEIGHT, :WIDTH]


def shows(window, env, expected, what, keep_as=None):
    """The window's image area once it equals `expected` (the X server may
    show a swap a moment after the preview made it); fails naming `what`."""
    deadline = time.time() + WAIT
    while True:
        shot = image_area(screenshot(window, env, keep_as))
        if np.array_equal(shot, expected):
            return shot
        if time.time() > deadline:
            raise AssertionError(f"{what}: the window's image differs from facet render's by up to "
                                 f"{np.abs(shot.astype(int) - expected).max()}")
        time.sleep(0.1)


def run_checks(work, env):
    scene = os.path.join(work, "scene.yaml")
    os.makedirs(os.path.join(work, "meshes"))
    sail = os.path.join(work, "meshes", "sail.obj")
    write_atomically(sail, sail_obj(0.2))
    look = os.path.join(work, "look.yaml")
    write_atomically(look, "extends: blinn-phong\n")
    write_atomically(scene, scene_text("[0.8, 0.2, 0.1]"))
    red = skio.imread(render(work, "ref-red"))
    preview = Preview(["scene.yaml", "-o", "snapshots"], work, env)
    window = None
    try:
        window = subprocess.run(["xdotool", "search", "--sync", "--name", "facet preview - scene.yaml"],
                                env=env, check=True, capture_output=True, text=True,
                                timeout=WAIT).stdout.split()[0]

        # 1. The window shows the scene's final image, pixel for pixel.
        _, at = preview.wait_for(r"^preview: frame 1: final")
        shot = screenshot(window, env)
        assert shot.shape[0] >= HEIGHT and shot.shape[1] > WIDTH, f"window {shot.shape}"
        shows(window, env, red, "the first image", "loaded")
        print("ok: the window shows facet render's image")

        # 2. An edit (the cube's colour) reloads and re-renders.
        write_atomically(scene, scene_text("[0.1, 0.3, 0.9]"))
        blue = skio.imread(render(work, "ref-blue"))
        _, at = preview.wait_for(r"^preview: reloading", at + 1)
        _, at = preview.wait_for(r"^preview: frame 1: final", at + 1)
        shows(window, env, blue, "the edited colour", "edited")
        print("ok: an edited colour shows")

        # 2b. So does an edit of a mesh the scene loads.
        write_atomically(sail, sail_obj(0.9))
        blue = skio.imread(render(work, "ref-blue"))
        _, at = preview.wait_for(r"^preview: reloading", at + 1)
        _, at = preview.wait_for(r"^preview: frame 1: final", at + 1)
        shows(window, env, blue, "the edited mesh")
        print("ok: an edited mesh shows")

        # 2c. And an edit of the style file the scene uses.
        write_atomically(look, "extends: blinn-phong\nbackground: [0.2, 0.3, 0.45]\n")
        blue = skio.imread(render(work, "ref-blue"))
        _, at = preview.wait_for(r"^preview: reloading", at + 1)
        _, at = preview.wait_for(r"^preview: frame 1: final", at + 1)
        shows(window, env, blue, "the edited style")
        print("ok: an edited style file shows")

        # 3. A broken scene: its error over the last image; the window stays.
        write_atomically(scene, scene_text("[0.1, 0.3, 0.9]", broken=True))
        line, at = preview.wait_for(r"^preview: error: ", at + 1)
        assert re.search(r"scene\.yaml:\d+:\d+: .*colour", line), f"error without file:line:col: {line}"
        deadline = time.time() + WAIT
        while True:  # the X server may show the drawing a moment later
            shot = image_area(screenshot(window, env, "error"))
            changed_rows = np.nonzero(np.any(shot != blue, axis=(1, 2)))[0]
            if len(changed_rows) > 0 or time.time() > deadline:
                break
            time.sleep(0.1)
        assert len(changed_rows) > 0, "no error shown over the image"
        # The message lists every key a material takes (more with each
        # material extension): several lines at 320 px, but never the whole
        # window, so the last good image shows below it.
        assert changed_rows[0] == 0 and changed_rows[-1] < HEIGHT - 24, \
            f"the error covers rows {changed_rows[0]}..{changed_rows[-1]}, not a band at the top"
        band = shot[:changed_rows[-1] + 1]
        reddish = (band[..., 0] > 180) & (band[..., 1] < 140) & (band[..., 2] < 140)
        assert reddish.sum() > 50, "the error band has no red text"
        assert np.array_equal(shot[changed_rows[-1] + 1:], blue[changed_rows[-1] + 1:]), \
            "the last good image is not kept below the error"
        assert preview.process.poll() is None, "the preview closed on an error"
        print(f"ok: the error shows over rows 0..{changed_rows[-1]} and the window stays")

        # 4. Fixed again: the error goes, the image comes back.
        write_atomically(scene, scene_text("[0.1, 0.3, 0.9]"))
        _, at = preview.wait_for(r"^preview: the scene loads again", at + 1)
        shows(window, env, blue, "the fixed scene")
        print("ok: a fixed scene clears the error")

        # 5. S writes a snapshot through render's writers: the same bytes.
        subprocess.run(["xdotool", "key", "--window", window, "s"], env=env, check=True, timeout=WAIT)
        _, at = preview.wait_for(r"^preview: snapshot of frame 1: wrote", at + 1)
        with open(os.path.join(work, "snapshots", "scene", "color.0001.png"), "rb") as f:
            snapshot = f.read()
        with open(os.path.join(work, "ref-blue", "scene", "color.0001.png"), "rb") as f:
            assert snapshot == f.read(), "the snapshot differs from facet render's file"
        print("ok: the snapshot equals facet render's file")

        # 6. Orbit with the mouse, print the camera (C), snapshot: pasting
        # the printed camera into the scene renders the snapshot exactly.
        # One step at a time: SDL takes a button only once the pointer has
        # entered its window. A drag lost by a busy X server is tried again.
        for attempt in range(3):
            for step in (["mousemove", "--window", window, "160", "120"], ["mousedown", "1"],
                         ["mousemove_relative", "--", "30", "-12"],
                         ["mousemove_relative", "--", "30", "-12"], ["mouseup", "1"]):
                subprocess.run(["xdotool", *step], env=env, check=True, timeout=WAIT)
                time.sleep(0.2)
            printed = len(preview.stdout)
            subprocess.run(["xdotool", "key", "--window", window, "c"], env=env, check=True, timeout=WAIT)
            preview.wait_for(r"^  far: ", printed, into=preview.stdout)
            with preview.lock:
                camera_text = "\n".join(line for line in preview.stdout[printed:]
                                        if not line.startswith("#")) + "\n"
            camera = yaml.safe_load(camera_text)["camera"]
            if camera["position"] != [0, 1.5, 4]:
                break
        assert camera["position"] != [0, 1.5, 4], f"the drag did not move the camera: {camera}"
        _, at = preview.wait_for(r"^preview: frame 1: final", at + 1)
        subprocess.run(["xdotool", "key", "--window", window, "s"], env=env, check=True, timeout=WAIT)
        _, at = preview.wait_for(r"^preview: snapshot of frame 1: wrote", at + 1)
        write_atomically(scene, scene_text("[0.1, 0.3, 0.9]", camera=camera_text))
        _, at = preview.wait_for(r"^preview: reloading", at + 1)
        moved = render(work, "ref-moved")
        with open(moved, "rb") as a, open(os.path.join(work, "snapshots", "scene", "color.0001.png"), "rb") as b:
            assert a.read() == b.read(), "the printed camera does not render the snapshot"
        print(f"ok: the printed camera ({camera['position']}) renders the snapshot")

        # 7. Time: R returns to the scene's camera (now the pasted one),
        # two steps right show frame 3, and playing for a second moves on.
        for key in ("r", "Right", "Right"):
            subprocess.run(["xdotool", "key", "--window", window, key], env=env, check=True, timeout=WAIT)
            time.sleep(0.2)
        _, at = preview.wait_for(r"^preview: frame 3: final", at + 1)
        shows(window, env, skio.imread(render(work, "ref-3", 3)), "frame 3")
        print("ok: stepping shows frame 3")
        subprocess.run(["xdotool", "key", "--window", window, "space"], env=env, check=True, timeout=WAIT)
        time.sleep(1.1)
        subprocess.run(["xdotool", "key", "--window", window, "space"], env=env, check=True, timeout=WAIT)
        line, at = preview.wait_for(r"^preview: frame \d+: final", at + 1)
        frame = int(re.search(r"frame (\d+)", line).group(1))
        # Which frame depends on timing (about 4 on); only that it moved is checked.
        assert frame != 3, "playing did not move on from frame 3"
        shows(window, env, skio.imread(render(work, "ref-played", frame)), f"frame {frame}")
        print(f"ok: playing moved on to frame {frame}")

        # 8. Q closes the window; the preview ends with 0.
        # The window may be gone before xdotool sends the key's release.
        subprocess.run(["xdotool", "key", "--window", window, "q"], env=env, stderr=subprocess.DEVNULL,
                       timeout=WAIT)
        assert preview.process.wait(timeout=WAIT) == 0, f"exit code {preview.process.returncode}"
        print("ok: q quits with 0")
    except BaseException:
        # What the preview said, and what the window showed last.
        with preview.lock:
            print("preview's standard error:\n  " + "\n  ".join(preview.lines))
            print("preview's standard output:\n  " + "\n  ".join(preview.stdout))
        try:
            skio.imsave(os.path.join(work, "last-screenshot.png"), screenshot(window, env),
                        check_contrast=False)
        except Exception as e:  # the window may be gone
            print(f"no last screenshot: {e}")
        raise
    finally:
        if preview.process.poll() is None:
            preview.process.kill()
            preview.process.wait()


if __name__ == "__main__":
    sys.exit(main())
