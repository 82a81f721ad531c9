% The DFT of N samples of signal(t) taken at fs, eqs. (1)-(3): single-sided amplitude.
t = (0:N - 1)/fs;
x = signal(t);
if strcmp(window, 'hann')
  w = 0.5 - 0.5*cos(2*pi*(0:N - 1)/N);    % periodic Hann window, eq. (6)
else
  w = ones(1, N);
end
g = mean(w);                               % coherent gain
X = fft(w.*x);
nb = floor(N/2) + 1;
amp = 2*abs(X(1:nb))/(N*g);                % eq. (3)
amp(1) = amp(1)/2;
if mod(N, 2) == 0, amp(nb) = amp(nb)/2; end
f = (0:nb - 1)*fs/N;
out.df = fs/N;
out.nyquist = fs/2;
out.duration = N/fs;
out.coherent_gain = g;
% samples all zero to rounding (a sine sampled at its zeros): no spectrum to speak of
tf = (0:64*N - 1)/(64*fs);
if max(abs(x)) <= 1e-12*max(abs(signal(tf)))
  disp('the samples are all zero to rounding: no peak, no leakage');
else
  % the largest local maximum at a bin frequency
  [~, kp] = max(amp);
  out.peak_frequency = f(kp);
  out.peak_amplitude = amp(kp);
  % leakage, eq. (5): power more than 2 bins from every peak above 1e-3 of the largest
  p = amp.^2/2; p(1) = amp(1)^2; if mod(N, 2) == 0, p(nb) = amp(nb)^2; end
  near = false(1, nb);
  for k = 1:nb
    left = -1; right = -1;
    if k > 1, left = amp(k - 1); end
    if k < nb, right = amp(k + 1); end
    if amp(k) > left && amp(k) >= right && amp(k) > 1e-3*max(amp)
      near(max(1, k - 2):min(nb, k + 2)) = true;
    end
  end
  out.leakage = max(0, 1 - sum(p(near))/sum(p));
end
