% Frequency response: |H(r)| = 1/|1 - r^2 + 2 i zeta r|, r = omega/omega_n, eq. (1).
H = @(r, z) 1./abs(1 - r.^2 + 2i*z*r);
z = zeta(1);                               % the first damping ratio's numbers
out.zeta = z;
out.Q = 1/(2*z);
if 2*z^2 < 1                               % a peak above r = 0, eq. (3)
  rp = sqrt(1 - 2*z^2);
  out.peak_r = rp;
  out.peak_omega = omega_n*rp;
  out.peak_height = 1/(2*z*sqrt(1 - z^2));
  r12 = sqrt(1 - 2*z^2 + [-1 1]*2*z*sqrt(1 - z^2));   % half-power points, eq. (5)
  if isreal(r12(1)) && r12(1) > 0
    out.bandwidth = omega_n*4*z*sqrt(1 - z^2)/(r12(2) + r12(1));  % r2 - r1 without cancellation
  end
else                                       % zeta >= 1/sqrt(2): |H| only falls from r = 0
  out.peak_r = 0;
  out.peak_omega = 0;
  out.peak_height = 1;
end
out.bandwidth_approx = 2*z*omega_n;        % eq. (6)
out.phase_at_resonance = angle(1 - 1 + 2i*z); % eq. (4): pi/2
% the peak found numerically: golden-section search on [0, 1.5]
g = (sqrt(5) - 1)/2; a = 0; b = 1.5;
c = b - g*(b - a); d = a + g*(b - a);
while b - a > 1e-12
  if H(c, z) >= H(d, z)
    b = d; d = c; c = b - g*(b - a);
  else
    a = c; c = d; d = a + g*(b - a);
  end
end
out.peak_omega_found = omega_n*(a + b)/2;
% (mechmat measures |H| and the phase in the time domain too, by DOP853 from the
% steady orbit, as a check of eqs. (1)-(2))
