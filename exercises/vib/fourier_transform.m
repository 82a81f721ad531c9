% The spectrum X(f) = int x(t) exp(-2 pi i f t) dt of a pulse of the given shape,
sinc0 = @(u) (u == 0) + (u ~= 0).*sin(u)./(u + (u == 0));   % sin(u)/u, 1 at u = 0
% duration and peak A centred at t_c, eq. (1), by the FFT of samples times dt, eq. (7).
tau = duration; sg = tau/6;
if strcmp(pulse, 'rectangular')
  xc = @(s) A*(abs(s) < tau/2) + A/2*(abs(abs(s) - tau/2) < 1e-9/fs);  % ends on a sample: the mean
  Xc = @(f) A*tau*sinc0(pi*f*tau);   f0 = 1/tau;                     % eq. (3)
elseif strcmp(pulse, 'triangular')
  xc = @(s) A*max(0, 1 - 2*abs(s)/tau);
  Xc = @(f) A*tau/2*sinc0(pi*f*tau/2).^2;   f0 = 2/tau;             % eq. (4)
elseif strcmp(pulse, 'gaussian')
  xc = @(s) A*exp(-s.^2/(2*sg^2));
  Xc = @(f) A*sg*sqrt(2*pi)*exp(-2*pi^2*sg^2*f.^2);                 % eq. (5)
  f0 = sqrt(log(2)/2)/(pi*sg);                                      % half amplitude
else
  xc = @(s) A*cos(pi*s/tau).*(abs(s) < tau/2);
  Xc = @(f) 2*A*tau/pi*cos(pi*f*tau)./(1 - 4*f.^2*tau^2);  f0 = 3/(2*tau);  % eq. (6)
end
out.area = Xc(0);
if strcmp(pulse, 'gaussian')
  out.half_amplitude_frequency = f0;
  out.half_amplitude_times_duration = f0*tau;
else
  out.first_zero = f0;
  out.first_zero_times_duration = f0*tau;
end
dt = 1/fs; m = floor(N/2); j = 0:N - 1;
x = xc((j - m)*dt);                        % sample m is the pulse centre
t0 = t_c - m*dt;
Xf = dt*exp(-2i*pi*(0:N - 1)/(N*dt)*t0).*fft(x);   % eq. (7), origin moved to t = 0
out.area_fft = real(Xf(1));
out.df = fs/N;
out.window = N/fs;
fk = (0:floor(N/2))/(N*dt); band = fk <= min(fs/4, 10/tau);
exact = Xc(fk(band)).*exp(-2i*pi*fk(band)*t_c);
out.max_error_band = max(abs(Xf(band) - exact))/Xc(0);
out.band = min(fs/4, 10/tau);
