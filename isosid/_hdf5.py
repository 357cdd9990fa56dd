"""One turn at a time on libhdf5 (Debian's, built without thread safety) for the package's
compiled calls that read or write HDF5 files: runs (isosid.run) and preparations
(isosid.prepare), which live in two modules and so cannot share a lock in C++."""
import threading

turn = threading.Lock()
