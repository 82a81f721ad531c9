% vib-absorber: a tuned mass on the main mass, steady amplitudes, Den Hartog
wn = sqrt(k1/m1); mu = m2/m1;
X = @(w, k2, c2) F0*[k2 - m2*w.^2 + 1i*w*c2; k2 + 1i*w*c2] ./ ...   % eq. (3)
    ((k1 - m1*w.^2).*(k2 - m2*w.^2) - m2*w.^2*k2 + 1i*w*c2.*(k1 - (m1 + m2)*w.^2));
A = m1*m2; B = m1*k2 + m2*(k1 + k2); C = k1*k2;           % eq. (4): A l^2 - B l + C = 0
l2 = (B + sqrt(B^2 - 4*A*C))/(2*A); l1 = C/(A*l2);
out.omega1 = sqrt(l1); out.omega2 = sqrt(l2);
out.tuned_omega = sqrt(k2/m2); out.mass_ratio = mu;
Xw = X(omega, k2, c2); out.X1 = abs(Xw(1)); out.X2 = abs(Xw(2));
out.omega_max = omega_max; if omega_max == 0, out.omega_max = 3*wn; end
f = 1/(1 + mu); out.tuning_opt = f;                        % eq. (5)
out.k2_opt = m2*(f*wn)^2;
out.zeta_opt = sqrt(3*mu/(8*(1 + mu)^3));                  % eq. (7)
out.c2_opt = 2*out.zeta_opt*m2*wn;
out.X1_fixed_points = F0/k1*sqrt(1 + 2/mu);                % eq. (6)
% the optimum curve's peak: the best of 2001 points, then golden sections
x1 = @(w) abs([1 0]*X(w, out.k2_opt, out.c2_opt));
w = (0:2000)*3*wn/2000; [~, i] = max(arrayfun(x1, w));
lo = w(max(i - 1, 1)); hi = w(min(i + 1, 2001)); g = (sqrt(5) - 1)/2;
while hi - lo > 1e-12*wn
  u = hi - g*(hi - lo); v = lo + g*(hi - lo);
  if x1(u) < x1(v), lo = u; else, hi = v; end
end
out.X1_opt_peak = x1((lo + hi)/2);
