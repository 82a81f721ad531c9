% Virtual work, eqs. (1)-(3): M = P dx_B/dtheta.
d = e - r * sin(theta);
s = sqrt(l^2 - d^2);
out.x_B = r * cos(theta) + s;
out.dx_dtheta = -r * sin(theta) + d * r * cos(theta) / s;
out.M = P * out.dx_dtheta;
% The same by the force balance of crank, rod and slider, eq. (4):
% unknowns [Ox Oy Ax Ay Bx By N M]
xa = r * cos(theta);  ya = r * sin(theta);  xb = out.x_B;  yb = e;
A = [1 0 1 0 0 0 0 0;
     0 1 0 1 0 0 0 0;
     0 0 -ya xa 0 0 0 1;
     0 0 -1 0 1 0 0 0;
     0 0 0 -1 0 1 0 0;
     0 0 0 0 -(yb - ya) xb - xa 0 0;
     0 0 0 0 -1 0 0 0;
     0 0 0 0 0 -1 1 0];
u = A \ [0; 0; 0; 0; 0; 0; P; 0];
out.F_rod = (u(5) * (xb - xa) + u(6) * (yb - ya)) / l;
out.N = u(7);
fprintf('M by virtual work %.15g N m, by the force balance %.15g N m\n', out.M, u(8));
