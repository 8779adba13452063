% Parallel leaf spring: two leaves of length L joined by a rigid stage, lateral force on the stage
% (SPACAR Light style, with a loop over the leaves)
clear; clc;
L = 0.05; w = 0.02; t = 0.3e-3; d = 0.03;   % leaf length, width, thickness, spacing [m]
nodes = zeros(5, 3);
for k = 1:2
  nodes(2*k-1, 1) = (k - 1)*d;                % base of leaf k
  nodes(2*k, 1) = (k - 1)*d;
  nodes(2*k, 2) = L;                          % top of leaf k
end
nodes(5, :) = [d/2 L 0];                      % stage centre
elements = [1 2; 3 4; 2 5; 4 5];
nprops(1).fix = true;
nprops(3).fix = true;
nprops(5).force = [1 0 0];                    % 1 N lateral
eprops(1).elems = [1 2];
eprops(1).emod = 210e9;
eprops(1).smod = 210e9/(2*(1 + 0.3));
eprops(1).dens = 7800;
eprops(1).cshape = 'rect';
eprops(1).dim = [w t];
eprops(1).orien = [0 0 1];
eprops(1).nbeams = 6;
eprops(1).flex = [1 2 3 4 5 6];
opt.loadsteps = 5;
opt.calcbuck = true;
opt.filename = 'leafspring';
out = spacarlight(nodes, elements, nprops, eprops, opt);
