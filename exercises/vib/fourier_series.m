% Fourier series of a square, sawtooth or triangle wave of period T and peak A:
% S_K(t) = a0/2 + sum (a_k cos k w t + b_k sin k w t), eq. (1).
K = terms; k = 1:K; w = 2*pi/T;
a = zeros(1, K); b = zeros(1, K);          % the closed forms, eqs. (6)-(8)
odd = mod(k, 2) == 1;
if strcmp(wave, 'square')
  b(odd) = 4*A./(k(odd)*pi);
elseif strcmp(wave, 'sawtooth')
  b = -2*A./(k*pi);
else
  a(odd) = 8*A./(pi^2*k(odd).^2);
end
% the same from one sampled period by the FFT, eq. (5)
N = 4096; while N < 256*K, N = 2*N; end
u = (0:N - 1)/N;
if strcmp(wave, 'square')
  f = A*sign(0.5 - u); f(1) = 0; f(N/2 + 1) = 0;   % jumps sampled at their mean
elseif strcmp(wave, 'sawtooth')
  f = A*(2*u - 1); f(1) = 0;
else
  v = u - (u >= 0.5); f = A*(1 - 4*abs(v));
end
X = fft(f);
a_fft = 2/N*real(X(2:K + 1)); b_fft = -2/N*imag(X(2:K + 1));
S = @(t) a*cos(w*k'*t) + b*sin(w*k'*t);    % partial sum from the exact coefficients
% the maximum of S_K at its known place, eqs. (10), (12), (14)
n = ceil(K/2);
if strcmp(wave, 'square')
  out.t_max = T/(4*n);
elseif strcmp(wave, 'sawtooth')
  out.t_max = -T/(2*(K + 1));
else
  out.t_max = 0;
end
out.overshoot = S(out.t_max) - A;
if ~strcmp(wave, 'triangle')
  out.overshoot_fraction = out.overshoot/(2*A);
end
out.gibbs_constant = integral(@(x) sin(x)./x, 0, pi)/pi - 0.5;
out.samples = N;
out.omega = w;
% beside: the maximum found by a scan, and that of the FFT's series
overshoot_scan = max(S(linspace(-T/2, T/2, 64*(K + 1)))) - A;
Sf = @(t) a_fft*cos(w*k'*t) + b_fft*sin(w*k'*t);
overshoot_fft = max(Sf(linspace(-T/2, T/2, 64*(K + 1)))) - A;
