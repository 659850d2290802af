"""The band envelope that "audio:B" bindings read, against a numpy reference of its definition
(docs/LIVE.md): frame k's window is the sound from k/fps to (k+1)/fps, mixed to mono, Hann
weighted, zero-padded to a power of two (at least 256); a band sums |X(f)|^2 over the bins with
low <= f < high, divided by its largest over the file."""
import math
import wave

import numpy as np
import pytest

import gridifs


def write_wav(path, samples, rate, channels=1):
    """Interleaved float samples in [-1, 1] as 16-bit PCM."""
    data = np.clip(np.round(np.asarray(samples) * 32767.0), -32768, 32767).astype("<i2")
    with wave.open(str(path), "wb") as w:
        w.setnchannels(channels)
        w.setsampwidth(2)
        w.setframerate(rate)
        w.writeframes(data.tobytes())


def reference_envelope(path, bands, fps):
    with wave.open(str(path), "rb") as w:
        rate, channels, n = w.getframerate(), w.getnchannels(), w.getnframes()
        pcm = np.frombuffer(w.readframes(n), dtype="<i2").astype(np.float64) / 32768.0
    mono = pcm.reshape(-1, channels).mean(axis=1)
    per_frame = rate / fps
    frames = max(1, math.ceil(len(mono) / per_frame))
    size = 256
    while size < math.ceil(per_frame) + 1:
        size *= 2
    out = np.zeros((len(bands), frames))
    freqs = np.arange(size // 2 + 1) * rate / size
    for k in range(frames):
        begin = math.floor(k * per_frame)
        end = min(len(mono), math.floor((k + 1) * per_frame))
        window = mono[begin:end] * (np.hanning(end - begin) if end - begin > 1 else 1.0)
        power = np.abs(np.fft.rfft(window, size)) ** 2
        for b, (lo, hi) in enumerate(bands):
            out[b, k] = power[(freqs >= lo) & (freqs < hi)].sum()
    largest = out.max(axis=1, keepdims=True)
    return np.divide(out, largest, out=np.zeros_like(out), where=largest > 0)


BANDS = [[20, 200], [200, 2000], [2000, 12000]]


def test_a_song_like_signal_matches_numpy(tmp_path):
    rate = 44100
    t = np.arange(3 * rate) / rate
    rng = np.random.default_rng(5)
    # A kick every half second, a chord swelling in and out, and hiss: every band moves.
    kick = np.sin(2 * np.pi * 60 * t) * np.exp(-((t % 0.5) * 12))
    chord = (np.sin(2 * np.pi * 440 * t) + np.sin(2 * np.pi * 660 * t)) * (0.5 - 0.5 * np.cos(2 * np.pi * t / 3))
    hiss = rng.normal(0, 0.05, len(t)) * (t > 1.5)
    left = 0.4 * kick + 0.2 * chord + hiss
    right = 0.4 * kick - 0.2 * chord
    stereo = np.stack([left, right], axis=1).reshape(-1)
    write_wav(tmp_path / "song.wav", stereo, rate, channels=2)
    for fps in (24.0, 25.0, 30.0):
        got = gridifs.audio_envelope(str(tmp_path / "song.wav"), BANDS, fps=fps)
        want = reference_envelope(tmp_path / "song.wav", BANDS, fps)
        assert got.shape == want.shape == (3, math.ceil(3 * fps))
        np.testing.assert_allclose(got, want, atol=2e-5, rtol=1e-4)


def test_silence_gives_exactly_zero_and_a_tone_its_band_max(tmp_path):
    rate = 22050
    silence = np.zeros(rate)
    tone = 0.5 * np.sin(2 * np.pi * 5000 * np.arange(rate) / rate)
    write_wav(tmp_path / "tone.wav", np.concatenate([silence, tone]), rate)
    got = gridifs.audio_envelope(str(tmp_path / "tone.wav"), BANDS, fps=24)
    assert got.shape == (3, 48)
    assert np.all(got[:, :24] == 0.0)
    assert got[2].max() == 1.0
    assert np.all(np.abs(got[2, 25:] - 1.0) < 0.02)


def test_bad_input_says_so(tmp_path):
    with pytest.raises(gridifs.Error, match="missing.wav"):
        gridifs.audio_envelope(str(tmp_path / "missing.wav"), BANDS)
    with pytest.raises(gridifs.Error, match="band"):
        gridifs.audio_envelope(str(tmp_path / "missing.wav"), [[200, 100]])
