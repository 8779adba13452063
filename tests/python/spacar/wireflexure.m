% Wire flexure: a round wire clamped at its base carries a rigid top; torque and axial load,
% released torsion mode on the wire (opt.rls), gravity
clear; clc;
nodes = [0 0 0; 0 0 0.04; 0.01 0 0.04];
elements = [1 2; 2 3];
nprops(1).fix = true;
nprops(3).force = [0 0 -5];
nprops(3).moment_initial = [0 0 0.01];
nprops(3).mass = 0.05;
eprops(1).elems = 1;
eprops(1).emod = 200e9;
eprops(1).smod = 77e9;
eprops(1).dens = 8000;
eprops(1).cshape = 'circ';
eprops(1).dim = 1e-3;
eprops(1).orien = [1 0 0];
eprops(1).nbeams = 8;
eprops(1).flex = 1:6;
opt.gravity = [0 0 -9.81];
opt.loadsteps = 4;
opt.filename = 'wireflexure';
out = spacarlight(nodes, elements, nprops, eprops, opt);
