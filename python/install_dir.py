"""Print where the module goes under an install prefix, relative to it (python/CMakeLists.txt).

The platlib folder of the first of this Python's schemes that lies under the prefix (Debian:
lib/python3.11/dist-packages under /usr/local, lib/python3/dist-packages under /usr); for any
other prefix, the system scheme's folder relative to its base, so PYTHONPATH must name it.
"""
import os
import sys
import sysconfig


def main():
    """Print the folder for the prefix given as the only argument."""
    prefix = os.path.normpath(sys.argv[1])
    names = sysconfig.get_scheme_names()
    schemes = ["deb_system", sysconfig.get_default_scheme(), "posix_prefix"]
    for scheme in (s for s in schemes if s in names):
        path = os.path.normpath(sysconfig.get_path("platlib", scheme))
        if path.startswith(prefix.rstrip("/") + "/"):
            print(os.path.relpath(path, prefix))
            return
    scheme = "deb_system" if "deb_system" in names else "posix_prefix"
    base = {"base": "/", "platbase": "/"}
    print(os.path.relpath(sysconfig.get_path("platlib", scheme, vars=base), "/"))


if __name__ == "__main__":
    main()
