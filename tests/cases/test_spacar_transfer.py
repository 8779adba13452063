#!/usr/bin/python3
"""SPACAR Light's refusals with opt.transfer (issue 10, item 7): the state-space model is built about
the unloaded equilibrium, so transfer together with calcbuck, with an applied load (standard or
initial, gravity) or with a prescribed motion (standard or initial) is a scene error (exit 2) naming
the field; a transfer_out on a clamped node is a scene error before anything is solved (formerly exit
3 after the load steps)."""
import sinewtest as st
from modal_util import beam_x

L, W, T = 1.0, 0.01, 1e-4
IO = {"transfer_in": ["force_z"], "transfer_out": ["displ_z"]}


def refused(name, nprops, opt, field):
    _, out = st.run("transfer_" + name, beam_x(L, W, T, 4, nprops, opt=dict({"transfer": True}, **opt)), expect_exit=2)
    st.check(field in out and "opt.transfer" in out, f"{name}: the refusal names {field} and opt.transfer: " + out.strip()[-300:])
    st.check("load step" not in out, f"{name}: refused before solving")


refused("calcbuck", {1: {"fix": True}, 2: IO}, {"calcbuck": True}, "opt.calcbuck")
refused("force_initial", {1: {"fix": True}, 2: dict(IO, force_initial=[0, 1e-3, 0])}, {}, "nprops(2).force_initial")
refused("moment_initial", {1: {"fix": True}, 2: dict(IO, moment_initial=[1e-3, 0, 0])}, {}, "nprops(2).moment_initial")
refused("displ_y", {1: {"fix": True}, 2: dict(IO, displ_y=1e-3)}, {}, "nprops(2).displ_y")
refused("displ_initial_x", {1: {"fix": True}, 2: dict(IO, displ_initial_x=1e-6)}, {}, "nprops(2).displ_initial_x")
refused("rot_initial", {1: dict(fix_pos=True, rot_initial=[0, 0, 0.01]), 2: IO}, {}, "nprops(1).rot_initial")
refused("gravity", {1: {"fix": True}, 2: IO}, {"gravity": [0, 0, -9.81]}, "opt.gravity")

# transfer_out on the clamped node: exit 2 naming the field, before any load step
_, out = st.run("transfer_out_clamped", beam_x(L, W, T, 4, {1: {"fix": True, "transfer_out": ["displ_z"]},
                                                             2: {"transfer_in": ["force_z"]}}, opt={"transfer": True}),
                expect_exit=2)
st.check("nprops(1).transfer_out" in out and "held" in out, "clamped transfer_out names nprops(1).transfer_out: " + out.strip()[-300:])
st.check("load step" not in out, "clamped transfer_out: refused before solving")
# the accepted combination still runs
_, out = st.run("transfer_ok", beam_x(L, W, T, 4, {1: {"fix": True}, 2: IO}, opt={"transfer": True, "nfreq": 2}))
st.done()
