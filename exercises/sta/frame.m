% Six equations, eq. (1): unknowns [Ax Ay Bx By Cx Cy];
% (Cx, Cy) is the force of the right body on the left body at C.
PL = [0 0 0];  PR = [0 0 0];        % [Fx Fy M about the origin] of each body's loads
for i = 1:size(loads, 1)
  p = loads(i, :);
  m = [p(3), p(4), p(1) * p(4) - p(2) * p(3)];
  if p(1) <= C(1)
    PL = PL + m;
  else
    PR = PR + m;
  end
end
M = [1 0 0 0 1 0;
     0 1 0 0 0 1;
     -A(2) A(1) 0 0 -C(2) C(1);
     0 0 1 0 -1 0;
     0 0 0 1 0 -1;
     0 0 -B(2) B(1) C(2) -C(1)];
x = M \ (-[PL'; PR']);
out.Ax = x(1); out.Ay = x(2); out.Bx = x(3); out.By = x(4); out.Cx = x(5); out.Cy = x(6);
