% State-space model of a cantilever flexure: force input and displacement/velocity outputs at the
% tip, modal damping 1 % (SPACAR Light's transfer options)
clear; clc;
nodes = [0 0 0; 0.1 0 0];
elements = [1 2];
nprops(1).fix = true;
nprops(2).transfer_in = {'force_z'};
nprops(2).transfer_out = {'displ_z', 'veloc_z'};
eprops(1).elems = [1];
eprops(1).emod = 70e9;
eprops(1).smod = 26e9;
eprops(1).dens = 2700;
eprops(1).cshape = 'rect';
eprops(1).dim = [10e-3 1e-3];
eprops(1).orien = [0 1 0];
eprops(1).nbeams = 8;
eprops(1).flex = 1:6;
opt.transfer = {true, 0.01};
opt.nfreq = 4;
opt.filename = 'statespace';
out = spacarlight(nodes, elements, nprops, eprops, opt);
