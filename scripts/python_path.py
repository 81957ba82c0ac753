#!/usr/bin/python3
"""Makes Debian's python3 find the `signorini` module of a build tree: writes the directory
into signorini.pth in the user's site-packages (on sys.path by default, no root needed).

    /usr/bin/python3 scripts/python_path.py BUILD/python
"""
import os
import site
import sys


def main():
    directory = os.path.abspath(sys.argv[1])
    if not site.ENABLE_USER_SITE:
        print("python_path: the user site-packages are disabled; use PYTHONPATH=" + directory)
        return
    user_site = site.getusersitepackages()
    os.makedirs(user_site, exist_ok=True)
    path = os.path.join(user_site, "signorini.pth")
    with open(path, "w") as f:
        f.write(directory + "\n")
    print(f"python_path: {path} -> {directory}")


if __name__ == "__main__":
    main()
