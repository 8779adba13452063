% Cross-flexure hinge, written as a SPACAR Light script (the model of runs/crosshinge.yaml)
clear; close all; clc;
%% nodes
L = 0.1;                     % leaf length [m]
nodes = [-L/2  0     0       % 1 base, leaf 1
          L/2  0     0       % 2 base, leaf 2
          L/2  L     0       % 3 top of leaf 1
         -L/2  L     0       % 4 top of leaf 2
          0    1.2*L 0];     % 5 load point on the top body
%% elements
elements = [1 3              % leaf 1
            2 4              % leaf 2
            3 4              % top body (rigid)
            4 5];            % top body (rigid)
%% node properties
nprops(1).fix = true;
nprops(2).fix = true;
nprops(5).force_initial = [0 -20 0];
nprops(5).moment = [0 0 0.5];
nprops(5).mass = 0.2;
nprops(5).mominertia = [1e-4 0 0 1e-4 0 1e-4];
%% element properties
eprops(1).elems = [1 2];
eprops(1).flex = 1:6;
eprops(1).emod = 210e9;
eprops(1).smod = 80e9;
eprops(1).dens = 7800;
eprops(1).cshape = 'rect';
eprops(1).dim = [50e-3 0.5e-3];
eprops(1).orien = [0 0 1];
eprops(1).nbeams = 4;
eprops(1).cw = 1;            % constrained warping
%% options
opt.loadsteps = 10;
opt.calcbuck = 1;
opt.stressperelement = true;
opt.filename = 'crosshinge';
out = spacarlight(nodes, elements, nprops, eprops, opt);
