% vib-beam-modes: Hermite beam elements against the roots beta L of eq. (2)
s = sqrt(E*I/(rho*A*L^4));
% the roots by Newton's method on the equation divided by cosh(bL), eq. (2)
bl = zeros(modes, 1);
for n = 1:modes
  switch bc
    case 'simply-supported', bl(n) = n*pi; continue
    case 'cantilever', x = (2*n - 1)*pi/2; sg = 1;    % cos x + sech x = 0
    otherwise,         x = (2*n + 1)*pi/2; sg = -1;   % cos x - sech x = 0
  end
  for it = 1:50
    dx = (cos(x) + sg/cosh(x))/(-sin(x) - sg*tanh(x)/cosh(x)); x = x - dx;
    if abs(dx) <= 2*eps*x, break; end
  end
  bl(n) = x;
end
wx = bl.^2*s;                                        % eq. (1)
% assembly of n elements: the Hermite stiffness and consistent mass
kel = @(h) E*I/h^3*[12 6*h -12 6*h; 6*h 4*h^2 -6*h 2*h^2; -12 -6*h 12 -6*h; 6*h 2*h^2 -6*h 4*h^2];
mel = @(h) rho*A*h/420*[156 22*h 54 -13*h; 22*h 4*h^2 13*h -3*h^2; 54 13*h 156 -22*h; -13*h -3*h^2 -22*h 4*h^2];
ns = [elements 4 8 16 32 64]; w1 = zeros(1, 6);
for i = 1:6
  n = ns(i); h = L/n; K = zeros(2*n + 2); M = K;
  for e = 1:n
    d = 2*e - 1:2*e + 2; K(d, d) = K(d, d) + kel(h); M(d, d) = M(d, d) + mel(h);
  end
  switch bc                                          % w, w' fixed by the supports
    case 'cantilever',       f = 3:2*n + 2;
    case 'simply-supported', f = [2:2*n, 2*n + 2];
    case 'clamped-clamped',  f = 3:2*n;
    otherwise,               f = 1:2*n + 2;
  end
  [V, D] = eig(K(f, f), M(f, f)); [lam, o] = sort(diag(D)); V = V(:, o);
  r = 2*strcmp(bc, 'free-free');                    % rigid-body modes: omega = 0
  % each frequency as the Rayleigh quotient of its mode, the strain energy
  % from the element curvatures (K phi would lose digits to cancellation)
  for j = r + 1:r + modes
    phi = zeros(2*n + 2, 1); phi(f) = V(:, j); U = 0;
    for e = 1:n
      v = phi(2*e - 1:2*e + 2); sl = (v(3) - v(1))/h;
      k0 = (6*sl - 4*v(2) - 2*v(4))/h; k1 = (-6*sl + 2*v(2) + 4*v(4))/h;
      U = U + E*I*h*(k0^2 + k0*k1 + k1^2)/3;
    end
    lam(j) = U/(phi'*M*phi);
    if i > 1, break; end
  end
  if i == 1, out.rigid_modes = r; w = sqrt(lam(r + 1:r + modes)); end
  w1(i) = sqrt(lam(r + 1));
end
out.omega1 = w(1); out.omega1_exact = wx(1);
p = polyfit(log(L./ns(2:6)), log(abs(w1(2:6)/wx(1) - 1)), 1);   % eq. (3): h^4
out.slope = p(1);
