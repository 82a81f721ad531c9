% vib-2dof: wall-k1-m1-k2-m2-k3-wall, natural frequencies and modes
M = [m1 0; 0 m2]; K = [k1 + k2, -k2; -k2, k2 + k3];     % eq. (1)
a = (k1 + k2)/m1; d = (k2 + k3)/m2; b = -k2/sqrt(m1*m2);  % M^-1/2 K M^-1/2 = [a b; b d]
l2 = (a + d)/2 + hypot((a - d)/2, b);                     % eq. (3)
l1 = 0; if l2 > 0, l1 = (k1*k2 + k1*k3 + k2*k3)/(m1*m2*l2); end
th = atan2(2*b, a - d)/2;                                 % eq. (4)
X = [-sin(th), cos(th); cos(th), sin(th)];                % columns: modes of [a b; b d]
Phi = diag(1./sqrt([m1 m2]))*X;                           % eq. (5): phi' M phi = 1
for j = 1:2
  if Phi(1, j) < 0 || (Phi(1, j) == 0 && Phi(2, j) < 0), Phi(:, j) = -Phi(:, j); end
end
out.omega1 = sqrt(l1); out.omega2 = sqrt(l2);
out.rigid_modes = (l1 == 0) + (l2 == 0);
if Phi(1, 1) ~= 0, out.amplitude_ratio_1 = Phi(2, 1)/Phi(1, 1); end
