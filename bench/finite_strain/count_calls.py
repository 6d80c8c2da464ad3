"""gdb script (run by count_calls.sh): counts the calls of the functions
listed in the environment variable COUNT_CALLS (one name per line) with
breakpoints that never stop. A breakpoint on a function of a shared library
also lands on its PLT stub, which calls through the library hit as well;
those locations are disabled, so that each call counts once."""
import os

import gdb


class Counter(gdb.Breakpoint):
    def __init__(self, spec):
        super().__init__(spec, internal=False)
        self.calls = 0

    def stop(self):
        self.calls += 1
        return False


gdb.execute("set pagination off")
gdb.execute("set print thread-events off")
# Stop at main: the program's libraries are loaded then, and the
# breakpoints resolve to their locations.
gdb.execute("break main")
gdb.execute("run")
counters = [Counter(name) for name in os.environ["COUNT_CALLS"].splitlines() if name]
for counter in counters:
    for location in counter.locations:
        if "@plt" in (location.function or ""):
            location.enabled = False
gdb.execute("continue")
with open(os.environ["COUNT_CALLS_OUT"], "w") as out:
    for counter in counters:
        functions = [l.function for l in counter.locations if l.enabled]
        out.write(f"{counter.location:62s} {counter.calls if functions else 'not found'}\n")
