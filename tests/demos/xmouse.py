#!/usr/bin/env python3
"""Real mouse and key events for a demo window under Xvfb, through the XTest extension (libXtst, by ctypes):
the path a lecturer's mouse takes through GLFW, which the scripted --keys input does not take.

    xmouse.py LOG "move 150 75; down; move 100 75; key s; up; key Escape"

waits until LOG shows that the window is open (the demo prints its window keys then), and sends the steps in
order: `move X Y` (the pointer, root coordinates: the window sits at the screen's top-left corner without a window
manager), `down` / `up` (the left button), `key NAME` (an X keysym name: s, Escape), `wait SECONDS`."""
import ctypes
import sys
import time


def main():
    log, steps = sys.argv[1], sys.argv[2]
    x11, xtst = ctypes.CDLL("libX11.so.6"), ctypes.CDLL("libXtst.so.6")
    x11.XOpenDisplay.restype = ctypes.c_void_p
    x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
    x11.XStringToKeysym.restype = ctypes.c_ulong
    x11.XStringToKeysym.argtypes = [ctypes.c_char_p]
    x11.XKeysymToKeycode.argtypes = [ctypes.c_void_p, ctypes.c_ulong]
    x11.XFlush.argtypes = [ctypes.c_void_p]
    xtst.XTestFakeMotionEvent.argtypes = [ctypes.c_void_p, ctypes.c_int, ctypes.c_int, ctypes.c_int, ctypes.c_ulong]
    xtst.XTestFakeButtonEvent.argtypes = [ctypes.c_void_p, ctypes.c_uint, ctypes.c_int, ctypes.c_ulong]
    xtst.XTestFakeKeyEvent.argtypes = [ctypes.c_void_p, ctypes.c_uint, ctypes.c_int, ctypes.c_ulong]
    display = x11.XOpenDisplay(None)
    if not display:
        sys.exit("xmouse.py: cannot open the display")
    deadline = time.time() + 60
    while "Window keys" not in open(log, errors="replace").read():
        if time.time() > deadline:
            sys.exit("xmouse.py: the window did not open within 60 s")
        time.sleep(0.2)
    time.sleep(1.0)  # the first frame
    for step in steps.split(";"):
        words = step.split()
        if not words:
            continue
        if words[0] == "wait":
            time.sleep(float(words[1]))
            continue
        if words[0] == "move":
            xtst.XTestFakeMotionEvent(display, -1, int(words[1]), int(words[2]), 0)
        elif words[0] in ("down", "up"):
            xtst.XTestFakeButtonEvent(display, 1, words[0] == "down", 0)
        elif words[0] == "key":
            code = x11.XKeysymToKeycode(display, x11.XStringToKeysym(words[1].encode()))
            xtst.XTestFakeKeyEvent(display, code, True, 0)
            xtst.XTestFakeKeyEvent(display, code, False, 0)
        else:
            sys.exit("xmouse.py: unknown step '%s'" % step)
        x11.XFlush(display)
        time.sleep(0.3)


if __name__ == "__main__":
    main()
