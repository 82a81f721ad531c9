% Reduce the forces (rows x y z Fx Fy Fz) and couples to R and M_O, eq. (1).
R = [0 0 0];
M = [0 0 0];
for i = 1:size(forces, 1)
  w = forces(i, 1:3) - O;
  f = forces(i, 4:6);
  R = R + f;
  M = M + [w(2) * f(3) - w(3) * f(2), w(3) * f(1) - w(1) * f(3), w(1) * f(2) - w(2) * f(1)];
end
for j = 1:size(couples, 1)
  M = M + couples(j, :);
end
out.Rx = R(1); out.Ry = R(2); out.Rz = R(3); out.R = norm(R);
out.MOx = M(1); out.MOy = M(2); out.MOz = M(3);
if norm(R) > 0
  out.pitch = dot(R, M) / dot(R, R);                 % eq. (3)
  P = O + [R(2) * M(3) - R(3) * M(2), R(3) * M(1) - R(1) * M(3), R(1) * M(2) - R(2) * M(1)] / dot(R, R);
  out.Px = P(1); out.Py = P(2); out.Pz = P(3);       % eq. (4)
  out.M_wrench = out.pitch * norm(R);
  if abs(dot(R, M)) <= 64 * eps * norm(R) * norm(M) * 10
    out.kind = 2;                                    % a single force
  else
    out.kind = 3;                                    % a wrench
  end
elseif norm(M) > 0
  out.kind = 1;                                      % a couple
else
  out.kind = 0;                                      % equilibrium
end
