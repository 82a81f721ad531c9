% A wave packet in a bar (omega = c k) or a beam (omega = a k^2), eqs. (1)-(2).
c = sqrt(E/rho); a = h*sqrt(E/(12*rho));
k0 = 2*pi/wavelength; sigma = cycles*wavelength;
if strcmp(medium, 'bar')
  omega = @(k) c*k; cg = c; cp = c; beta = 0;   % non-dispersive: c_p = c_g = c
else
  omega = @(k) a*k.^2; cg = 2*a*k0; cp = a*k0; beta = 2*a*t/sigma^2;
end
w0 = omega(k0);
sigma_t = sigma*sqrt(1 + beta^2);          % eq. (8)
out.k0 = k0;
out.omega0 = w0;
out.f0 = w0/(2*pi);
out.phase_velocity = cp;                   % eq. (3)
out.group_velocity = cg;                   % eq. (4)
out.ratio = cg/cp;
out.centre_speed = cg;
out.travel = cg*t;
out.crest_slip = (cg - cp)*t/wavelength;
out.width0 = sigma/sqrt(2);
out.width = sigma_t/sqrt(2);
out.spread = sigma_t/sigma;
% measured: the packet's modes (FFT of eq. 5 sampled) each advanced by exp(-i omega(k) t), eq. (6)
xl = -9*sigma; xr = cg*t + 9*sigma_t; L = xr - xl;
N = 64; while pi*N/L < k0 + 10/sigma, N = 2*N; end
x = xl + (0:N - 1)*L/N;
psi0 = A*exp(-x.^2/(2*sigma^2) + 1i*k0*x);
C = fft(psi0)/N;
kk = 2*pi/L*[0:N/2 - 1, -N/2:-1];          % wavenumbers of the FFT bins
psit = N*ifft(C.*exp(-1i*omega(kk)*t));
p0 = abs(psi0).^2; pt = abs(psit).^2;
xc0 = sum(p0.*x)/sum(p0); xct = sum(pt.*x)/sum(pt);
out.centre_speed_measured = (xct - xc0)/t;
out.travel_measured = xct - xc0;
out.width0_measured = sqrt(sum(p0.*(x - xc0).^2)/sum(p0));
out.width_measured = sqrt(sum(pt.*(x - xct).^2)/sum(pt));
out.spread_measured = out.width_measured/out.width0_measured;
