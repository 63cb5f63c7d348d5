"""Nothing lost on failure (docs/runtime.md, "Result files"): a writer stopped mid-run leaves the
previous result intact. rbdc-sim (C++, rbdc::ResultFile) is stopped by SIGTERM and by SIGINT while
writing its CSV; a Python writer (tools/result_files.py) by SIGINT inside replacing().

Usage: test_interrupted_writers.py RBDC_SIM SOURCE_DIR
"""
import glob
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest

RBDC_SIM, SOURCE_DIR = sys.argv[1], sys.argv[2]


def wait_for(condition, seconds=60):
    deadline = time.monotonic() + seconds
    while not condition():
        if time.monotonic() > deadline:
            raise AssertionError("timed out")
        time.sleep(0.05)


class InterruptedWriters(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory(prefix="rbdc-interrupted-")
        self.addCleanup(self.folder.cleanup)
        self.result = os.path.join(self.folder.name, "result")

    def partials(self):
        return glob.glob(self.result + ".*.partial")

    def interrupt(self, command, sig, started):
        """Runs `command` until `started()`, sends `sig`, returns the exit code."""
        child = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            wait_for(lambda: started() or child.poll() is not None)
            self.assertIsNone(child.poll(), "the writer ended before it could be interrupted")
            child.send_signal(sig)
            return child.wait(timeout=60)
        finally:
            if child.poll() is None:
                child.kill()
                child.wait()

    def test_rbdc_sim_csv_survives_sigterm_and_sigint(self):
        csv = self.result + ".csv"
        self.result = csv
        subprocess.run([RBDC_SIM, "--quiet", "--duration", "0.05", "--out", csv], check=True,
                       stdout=subprocess.DEVNULL)
        with open(csv, "rb") as f:
            previous = f.read()
        self.assertGreater(previous.count(b"\n"), 10)
        for sig in (signal.SIGTERM, signal.SIGINT):
            code = self.interrupt([RBDC_SIM, "--quiet", "--duration", "600", "--out", csv], sig,
                                  lambda: any(os.path.getsize(p) > 100_000 for p in self.partials()))
            self.assertEqual(code, -sig)
            with open(csv, "rb") as f:
                self.assertEqual(f.read(), previous, "rbdc-sim's previous CSV changed after %s" % sig.name)
            for p in self.partials():  # a killed process leaves its temporary file (ignored by git)
                os.remove(p)

    def test_python_writer_survives_sigint(self):
        with open(self.result, "w") as f:
            f.write("previous\n")
        writer = ("import sys, time; sys.path.insert(0, %r)\n"
                  "from result_files import replacing\n"
                  "with replacing(%r) as partial, open(partial, 'w') as out:\n"
                  "    out.write('half of the new result'); out.flush(); time.sleep(600)\n"
                  % (os.path.join(SOURCE_DIR, "tools"), self.result))
        code = self.interrupt([sys.executable, "-c", writer], signal.SIGINT,
                              lambda: any(os.path.getsize(p) > 0 for p in self.partials()))
        self.assertNotEqual(code, 0)
        with open(self.result) as f:
            self.assertEqual(f.read(), "previous\n")
        self.assertEqual(self.partials(), [], "KeyboardInterrupt removes the temporary file")


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
