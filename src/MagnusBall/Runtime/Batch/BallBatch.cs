using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using MagnusBall.Aerodynamics;
using MagnusBall.Flight;
using MagnusBall.Integration;

namespace MagnusBall.Batch
{
    /// <summary>
    /// Many balls under one <see cref="FlightModel"/> (a crowd, particles, an AI's candidate shots), stepped together by
    /// fixed-step RK4 with each ball's landing on a ground plane located inside the step. Structure of arrays, stepped
    /// with <see cref="Vector{T}"/> of doubles where the hardware accelerates it, ball by ball otherwise. Allocates only
    /// when constructed.
    /// </summary>
    /// <remarks>
    /// <para>Each ball's flight is the single-ball path's, number for number: the same RK4 arithmetic as
    /// <see cref="Integration.RungeKutta4"/> (lanes of a vector compute exactly what the scalar code computes: IEEE
    /// add, multiply, divide and square root, no fused operations), and the landing located on the step's cubic
    /// Hermite by the same <see cref="HermiteSegment.TryFindCrossing(in Plane, CrossingDirection, bool, out double)"/>
    /// as a <see cref="Flight.FlightStepper"/> with a ground event. A ball that lands stops there: its state becomes the
    /// landing state and later steps leave it alone.</para>
    /// <para>Vectorised laws: drag none, constant or Stepanek; lift none, constant, linear in spin or Stepanek; spin
    /// decay none or exponential; a uniform wind. Any other model (a wind profile, other laws, a law of your own) and
    /// any runtime where <see cref="Vector.IsHardwareAccelerated"/> is false steps ball by ball through the model's
    /// kernel, with the same results (see <see cref="IsVectorized"/>).</para>
    /// <para>A ball whose step would overflow (a step far beyond RK4's stability limit) keeps its last finite state
    /// and stops (<see cref="HasDiverged"/>). Not thread-safe; the model may be shared.</para>
    /// </remarks>
    public sealed class BallBatch
    {
        private const double HermiteBound = 0.15; // > 4/27, the largest |h10| and |h11| of the cubic Hermite basis on [0, 1]

        private readonly int _width;
        private readonly double[] _px, _py, _pz, _vx, _vy, _vz, _wx, _wy, _wz, _t;
        private readonly double[] _ax, _ay, _az, _sx, _sy, _sz; // the derivative at the current state (acceleration, spin acceleration)
        private readonly long[] _active;                       // -1 while the ball flies, 0 once it landed or diverged (and for padding)
        private readonly bool[] _startsFlight;
        private readonly bool[] _diverged;
        private readonly FlightState[] _landing;
        private readonly VectorLaws _laws;
        private readonly FlightEventSet _landingEvents;
        private readonly FlightEvent[] _found;
        private readonly SavedBall[]? _saved; // where a law is the user's own: each ball as it was before this Advance call
        private long _calls; // Advance calls that saved balls (SavedBall.Call; 0 is no call)
        private int _count;

        /// <summary>Creates an empty batch.</summary>
        /// <param name="model">The flight model every ball flies under.</param>
        /// <param name="capacity">The most balls it holds; 1 to 10,000,000.</param>
        /// <param name="ground">The plane a ball lands on (crossing it against its normal); default <see cref="Plane.Ground(FlightModel, Vector3d)"/>.</param>
        /// <exception cref="ArgumentException">model is null or capacity is out of range.</exception>
        public BallBatch(FlightModel model, int capacity, Plane? ground = null)
        {
            Model = Require.NotNull(model, nameof(model));
            if (capacity < 1 || capacity > 10_000_000)
            {
                throw new ArgumentOutOfRangeException(nameof(capacity), capacity, $"capacity must be in [1, 10000000]; got {capacity}.");
            }

            Ground = ground ?? Plane.Ground(model);
            // The landing is the flight core's event: a set with this ground and no apex, scanned as a FlightStepper scans
            // a piece, ended by FlightEventSet.CountUntil's rule.
            _landingEvents = new FlightEventSet(Vector3d.Zero, Ground);
            _found = new FlightEvent[_landingEvents.MaximumEventsPerStep];
            _laws = VectorLaws.For(model);
            IsVectorized = Vector.IsHardwareAccelerated && _laws.Supported;
            _width = IsVectorized ? Vector<double>.Count : 1;
            int length = (capacity + _width - 1) / _width * _width;
            Capacity = capacity;
            _px = new double[length];
            _py = new double[length];
            _pz = new double[length];
            _vx = new double[length];
            _vy = new double[length];
            _vz = new double[length];
            _wx = new double[length];
            _wy = new double[length];
            _wz = new double[length];
            _t = new double[length];
            _ax = new double[length];
            _ay = new double[length];
            _az = new double[length];
            _sx = new double[length];
            _sy = new double[length];
            _sz = new double[length];
            _active = new long[length];
            _startsFlight = new bool[length];
            _diverged = new bool[length];
            _landing = new FlightState[length];
            if (model.Kernel.RunsUserCode)
            {
                _saved = new SavedBall[length];
            }
        }

        /// <summary>The flight model.</summary>
        public FlightModel Model { get; }

        /// <summary>The plane the balls land on.</summary>
        public Plane Ground { get; }

        /// <summary>The most balls the batch holds.</summary>
        public int Capacity { get; }

        /// <summary>The balls in the batch.</summary>
        public int Count => _count;

        /// <summary>
        /// True when the batch steps <see cref="Vector{T}.Count"/> balls at a time (the hardware accelerates
        /// <see cref="Vector{T}"/> and the model's laws have vector forms); false when it steps ball by ball. The results
        /// are the same either way.
        /// </summary>
        public bool IsVectorized { get; }

        /// <summary>Adds a ball; it flies from <paramref name="state"/> (evaluates its derivative once).</summary>
        /// <param name="state">The start state; every component finite.</param>
        /// <returns>The ball's index.</returns>
        /// <exception cref="ArgumentException">The state is not finite.</exception>
        /// <exception cref="InvalidOperationException">The batch is full.</exception>
        /// <remarks>A law of your own that throws while the derivative is evaluated: its exception, and no ball added.</remarks>
        public int Add(in FlightState state)
        {
            CheckState(state);
            if (_count == Capacity)
            {
                throw new InvalidOperationException($"The batch is full ({Capacity} balls).");
            }

            int index = _count;
            Place(index, state); // may run a user's law, which may throw: the ball is counted only once it is in place
            _count++;
            return index;
        }

        /// <summary>Restarts ball <paramref name="index"/> from <paramref name="state"/> (clears its landing).</summary>
        /// <param name="index">The ball, 0 to Count - 1.</param>
        /// <param name="state">The new start state; every component finite.</param>
        /// <exception cref="ArgumentException">The index is out of range or the state is not finite.</exception>
        public void Reset(int index, in FlightState state)
        {
            CheckIndex(index);
            CheckState(state);
            Place(index, state);
        }

        /// <summary>Removes every ball.</summary>
        public void Clear()
        {
            Array.Clear(_active, 0, _active.Length);
            _count = 0;
        }

        /// <summary>Ball <paramref name="index"/>'s current state (its landing state once it landed).</summary>
        /// <param name="index">The ball, 0 to Count - 1.</param>
        /// <exception cref="ArgumentOutOfRangeException">The index is out of range.</exception>
        public FlightState GetState(int index)
        {
            CheckIndex(index);
            return new FlightState(
                new Vector3d(_px[index], _py[index], _pz[index]),
                new Vector3d(_vx[index], _vy[index], _vz[index]),
                new Vector3d(_wx[index], _wy[index], _wz[index]),
                _t[index]);
        }

        /// <summary>True while ball <paramref name="index"/> flies (it has neither landed nor diverged).</summary>
        /// <param name="index">The ball, 0 to Count - 1.</param>
        /// <exception cref="ArgumentOutOfRangeException">The index is out of range.</exception>
        public bool IsFlying(int index)
        {
            CheckIndex(index);
            return _active[index] != 0;
        }

        /// <summary>True when ball <paramref name="index"/> stopped because a step would have overflowed.</summary>
        /// <param name="index">The ball, 0 to Count - 1.</param>
        /// <exception cref="ArgumentOutOfRangeException">The index is out of range.</exception>
        public bool HasDiverged(int index)
        {
            CheckIndex(index);
            return _diverged[index];
        }

        /// <summary>Ball <paramref name="index"/>'s landing, when it has landed.</summary>
        /// <param name="index">The ball, 0 to Count - 1.</param>
        /// <param name="landing">The state at the landing (time, position, velocity, spin); default when none.</param>
        /// <returns>True when the ball has landed.</returns>
        /// <exception cref="ArgumentOutOfRangeException">The index is out of range.</exception>
        public bool TryGetLanding(int index, out FlightState landing)
        {
            CheckIndex(index);
            bool landed = _active[index] == 0 && !_diverged[index];
            landing = landed ? _landing[index] : default;
            return landed;
        }

        /// <summary>
        /// Advances every flying ball by <paramref name="count"/> RK4 steps of <paramref name="step"/> seconds (a 60 FPS
        /// frame at 1/240 s: count 4), locating each landing inside its step. 4 evaluations per ball and step. Allocates nothing.
        /// </summary>
        /// <remarks>
        /// Only a law of your own can throw here (the built-in laws do not). Its exception comes out of this call, and every
        /// ball is then as it was before the call (a batch with such a law saves each ball before it moves it).
        /// </remarks>
        /// <param name="step">The step, s; finite and &gt; 0.</param>
        /// <param name="count">The steps, 0 to 1,000,000.</param>
        /// <exception cref="ArgumentOutOfRangeException">An argument is out of range (nothing changes).</exception>
        public void Advance(double step, int count = 1)
        {
            Require.Step(step, nameof(step));
            if (count < 0 || count > 1_000_000)
            {
                throw new ArgumentOutOfRangeException(nameof(count), count, $"count must be in [0, 1000000]; got {count}.");
            }

            if (!IsVectorized)
            {
                if (_saved != null)
                {
                    RunScalarUndoable(step, count);
                }
                else
                {
                    RunScalarAll(step, count, 0);
                }

                return;
            }

            for (int i = 0; i < count; i++)
            {
                for (int start = 0; start < _count; start += _width)
                {
                    StepVector(start, step);
                }
            }
        }

        private void Place(int index, in FlightState state)
        {
            StateDerivative derivative = Model.Derivative(state);
            Store(index, state, derivative);
            _active[index] = -1;
            _startsFlight[index] = true;
            _diverged[index] = false;
            _landing[index] = default;
        }

        // The active balls of the lanes [start, start + width), one by one.
        private void StepScalarLanes(int start, double step)
        {
            int end = Math.Min(start + _width, _count);
            for (int index = start; index < end; index++)
            {
                if (_active[index] != 0)
                {
                    StepScalar(index, step);
                }
            }
        }

        // One ball, one step: the model's kernel (RungeKutta4's arithmetic), then the landing.
        private void StepScalar(int i, double step)
        {
            Load(i, out FlightState start, out StateDerivative k1);
            FlightState end = Model.Kernel.RungeKutta4(start, k1, step, out StateDerivative k);
            Finish(i, start, k1, end, k);
        }

        // Ball by ball, each through all its steps: the balls are independent, so the order does not change a number. With a
        // call number (not 0), each flying ball is first saved in _saved, marked with it (RunScalarUndoable).
        private void RunScalarAll(double step, int count, long call)
        {
            for (int index = 0; index < _count && count > 0; index++)
            {
                if (_active[index] != 0)
                {
                    if (call != 0)
                    {
                        ref SavedBall ball = ref _saved![index];
                        Load(index, out ball.State, out ball.Derivative);
                        ball.StartsFlight = _startsFlight[index];
                        ball.Call = call;
                    }

                    RunScalar(index, step, count);
                }
            }
        }

        // The ball-by-ball loop where a law is the user's own: if the user's code throws, every ball saved this call (those
        // it moved, and the one whose law threw) is put back as it was, flying, before the exception goes on.
        private void RunScalarUndoable(double step, int count)
        {
            SavedBall[] saved = _saved!;
            long call = ++_calls;
            try
            {
                RunScalarAll(step, count, call);
            }
            catch
            {
                for (int i = 0; i < _count; i++)
                {
                    if (saved[i].Call == call)
                    {
                        // It flew when saved: not landed, not diverged.
                        Store(i, saved[i].State, saved[i].Derivative);
                        _startsFlight[i] = saved[i].StartsFlight;
                        _active[i] = -1;
                        _diverged[i] = false;
                        _landing[i] = default;
                    }
                }

                throw;
            }
        }

        // Ball i (flying), count >= 1 steps: StepScalar's step and Finish's rules, with the state kept in locals between steps,
        // so the ball's sixteen arrays are read once and written once a call instead of once a step (under Mono, where the
        // batch goes ball by ball, 10,000 balls through a frame went from 15.8 to 12.9-13.3 ms).
        private void RunScalar(int i, double step, int count)
        {
            Load(i, out FlightState state, out StateDerivative k1);
            for (int n = 0; n < count; n++)
            {
                FlightState end = Model.Kernel.RungeKutta4(state, k1, step, out StateDerivative k);
                if (!FlightStepper.Takes(state, end, k) || !_landingEvents.SurelyClear(state, k1, end, k))
                {
                    // A refused step, or one that may hold the landing: the whole of Finish, which stores the ball, and which,
                    // unless the ball stopped, stores (end, k), the pair the next step starts from.
                    Finish(i, state, k1, end, k);
                    if (_active[i] == 0)
                    {
                        return;
                    }
                }

                _startsFlight[i] = false;
                state = end;
                k1 = k;
            }

            Store(i, state, k1);
        }

        // After ball i's step from (start, k1) to (end, k), by the flight core's rules: a step the core refuses
        // (FlightStepper.Takes) stops the ball at its last finite state; otherwise the core's event scan on the step's
        // Hermite and its stop rule (FlightEventSet.CountUntil) find the landing, where the ball stops.
        private void Finish(int i, in FlightState start, in StateDerivative k1, in FlightState end, in StateDerivative k)
        {
            if (!FlightStepper.Takes(start, end, k))
            {
                _active[i] = 0;
                _diverged[i] = true;
                Store(i, start, k1);
                return;
            }

            if (_landingEvents.SurelyClear(start, k1, end, k))
            {
                // No landing in this step, surely (the flight core's quick test: a scan of the segment would find none), so
                // the 304-byte segment is not built: what the scalar path (ball by ball where Vector<double> is not
                // accelerated, as under Mono) pays on most steps.
                Store(i, end, k);
                _startsFlight[i] = false;
                return;
            }

            var segment = HermiteSegment.OfTakenStep(start, k1, end, k);
            Span<FlightEvent> found = _found;
            int count = _landingEvents.Scan(ref segment, _found, _startsFlight[i], landings: true);
            FlightEventSet.CountUntil(found.Slice(0, count), FlightEventKinds.Landing, out int stop);
            if (stop >= 0)
            {
                FlightState landing = _found[stop].State;
                _landing[i] = landing;
                _active[i] = 0;
                Store(i, landing, k);
            }
            else
            {
                Store(i, end, k);
            }

            _startsFlight[i] = false;
        }

        // Ball i's state and its derivative, as Store wrote them.
        private void Load(int i, out FlightState state, out StateDerivative derivative)
        {
            state = new FlightState(
                new Vector3d(_px[i], _py[i], _pz[i]), new Vector3d(_vx[i], _vy[i], _vz[i]), new Vector3d(_wx[i], _wy[i], _wz[i]), _t[i]);
            derivative = new StateDerivative(state.Velocity, new Vector3d(_ax[i], _ay[i], _az[i]), new Vector3d(_sx[i], _sy[i], _sz[i]));
        }

        private void Store(int i, in FlightState s, in StateDerivative d)
        {
            _px[i] = s.Position.X;
            _py[i] = s.Position.Y;
            _pz[i] = s.Position.Z;
            _vx[i] = s.Velocity.X;
            _vy[i] = s.Velocity.Y;
            _vz[i] = s.Velocity.Z;
            _wx[i] = s.AngularVelocity.X;
            _wy[i] = s.AngularVelocity.Y;
            _wz[i] = s.AngularVelocity.Z;
            _t[i] = s.Time;
            _ax[i] = d.Acceleration.X;
            _ay[i] = d.Acceleration.Y;
            _az[i] = d.Acceleration.Z;
            _sx[i] = d.AngularAcceleration.X;
            _sy[i] = d.AngularAcceleration.Y;
            _sz[i] = d.AngularAcceleration.Z;
        }

        // One RK4 step of the lanes [start, start + width): RungeKutta4's arithmetic lane by lane. Lanes that do not fly
        // (landed, diverged, padding) keep their values; lanes whose step may hold a landing are finished one by one
        // through the scalar path's Finish with the very numbers computed here, and lanes that overflowed take the
        // scalar path's whole step (StepScalar).
        private void StepVector(int start, double step)
        {
            var active = new Vector<long>(_active, start);
            if (Vector.EqualsAll(active, Vector<long>.Zero))
            {
                return;
            }

            ref readonly VectorLaws laws = ref _laws;
            var h = new Vector<double>(step);
            var half = new Vector<double>(0.5 * step);
            var sixth = new Vector<double>(step / 6.0);
            var two = new Vector<double>(2.0);

            Vector<double> px = new Vector<double>(_px, start), py = new Vector<double>(_py, start), pz = new Vector<double>(_pz, start);
            Vector<double> vx = new Vector<double>(_vx, start), vy = new Vector<double>(_vy, start), vz = new Vector<double>(_vz, start);
            Vector<double> wx = new Vector<double>(_wx, start), wy = new Vector<double>(_wy, start), wz = new Vector<double>(_wz, start);
            Vector<double> ax = new Vector<double>(_ax, start), ay = new Vector<double>(_ay, start), az = new Vector<double>(_az, start);
            Vector<double> sx = new Vector<double>(_sx, start), sy = new Vector<double>(_sy, start), sz = new Vector<double>(_sz, start);
            if (!Vector.LessThanOrEqualAll(wx * wx + wy * wy + wz * wz, new Vector<double>(double.MaxValue)))
            {
                // A spin rate past about 1.3e154 rad/s: the lanes' plain |w| (VectorLaws) would be infinite where the kernel's
                // scaled one is not, so these balls take the per-ball kernel step, whose numbers the vector lanes equal
                // everywhere else.
                StepScalarLanes(start, step);
                return;
            }

            bool spins = laws.Decay != VectorLaws.DecayKind.None;

            // The kernel's inner-stage spin rates where it scales them from the step's (FlightKernel.StageSpinFactors).
            bool scaled = laws.ScalesStageSpinRates && FlightKernel.WithinOneTimeConstant(laws.DecayFactor, step); // the kernel's condition
            Vector<double> startRate = default;
            double f2 = 0, f3 = 0, f4 = 0;
            if (scaled)
            {
                // The kernel's step rate is Vector3d.LengthOf, which scales where |w|^2 is not a normal double (|w| below
                // about 1.5e-154 rad/s; above 1.3e154 the step went ball by ball above). Such a lane's plain square root may
                // differ, but its scaled rates (|g| between 1/4 and 1) then lie below the fold's 1e-50, so the lane is marked
                // for the per-ball step (VectorLaws.Rates), where the kernel's own numbers are used.
                startRate = Vector.SquareRoot(wx * wx + wy * wy + wz * wz);
                FlightKernel.StageSpinFactors(laws.DecayFactor, step, out f2, out f3, out f4);
            }

            // k2, k3, k4 and the end rates from one evaluation site (the laws inlined once), RungeKutta4's grouping.
            Vector<double> v2x = default, v2y = default, v2z = default, v3x = default, v3y = default, v3z = default;
            Vector<double> a2x = default, a2y = default, a2z = default, a3x = default, a3y = default, a3z = default;
            Vector<double> s2x = default, s2y = default, s2z = default, s3x = default, s3y = default, s3z = default;
            Vector<double> vkx = vx, vky = vy, vkz = vz, akx = ax, aky = ay, akz = az, skx = sx, sky = sy, skz = sz;
            Vector<double> npx = px, npy = py, npz = pz, nvx, nvy, nvz, nwx = wx, nwy = wy, nwz = wz;
            Vector<double> nax, nay, naz, nsx, nsy, nsz;
            // Lanes where a decaying spin's stage spin has squares past double.MaxValue (the check above sees only the
            // start spin; with an exponential decay and a step several time constants long, the stage spins of RK4 grow):
            // the kernel's step for those balls, as for the start spin. Likewise lanes the laws mark as computed otherwise than
            // the kernel computes them (Stepanek's lift outside its folded form's range).
            Vector<long> perBall = Vector<long>.Zero;
            for (int stage = 0; ; stage++)
            {
                if (stage < 3)
                {
                    Vector<double> c = stage == 2 ? h : half;
                    nvx = vx + c * akx;
                    nvy = vy + c * aky;
                    nvz = vz + c * akz;
                    if (spins)
                    {
                        nwx = wx + c * skx;
                        nwy = wy + c * sky;
                        nwz = wz + c * skz;
                    }
                }
                else
                {
                    npx = px + (vx + two * (v2x + v3x) + vkx) * sixth;
                    npy = py + (vy + two * (v2y + v3y) + vky) * sixth;
                    npz = pz + (vz + two * (v2z + v3z) + vkz) * sixth;
                    nvx = vx + (ax + two * (a2x + a3x) + akx) * sixth;
                    nvy = vy + (ay + two * (a2y + a3y) + aky) * sixth;
                    nvz = vz + (az + two * (a2z + a3z) + akz) * sixth;
                    if (spins)
                    {
                        nwx = wx + (sx + two * (s2x + s3x) + skx) * sixth;
                        nwy = wy + (sy + two * (s2y + s3y) + sky) * sixth;
                        nwz = wz + (sz + two * (s2z + s3z) + skz) * sixth;
                    }
                    else
                    {
                        nwx = wx + sx * sixth;
                        nwy = wy + sy * sixth;
                        nwz = wz + sz * sixth;
                    }
                }

                if (spins)
                {
                    perBall |= Vector.GreaterThan(nwx * nwx + nwy * nwy + nwz * nwz, new Vector<double>(double.MaxValue));
                }

                bool stageRate = scaled && stage < 3;
                Vector<double> rate = stageRate ? startRate * new Vector<double>(stage == 0 ? f2 : stage == 1 ? f3 : f4) : default;
                laws.Rates(nvx, nvy, nvz, nwx, nwy, nwz, rate, stageRate, out nax, out nay, out naz, out nsx, out nsy, out nsz, out Vector<long> unfolded);
                perBall |= unfolded;
                if (stage == 3)
                {
                    break;
                }

                if (stage == 0)
                {
                    v2x = nvx;
                    v2y = nvy;
                    v2z = nvz;
                    a2x = nax;
                    a2y = nay;
                    a2z = naz;
                    s2x = nsx;
                    s2y = nsy;
                    s2z = nsz;
                }
                else if (stage == 1)
                {
                    v3x = nvx;
                    v3y = nvy;
                    v3z = nvz;
                    a3x = nax;
                    a3y = nay;
                    a3z = naz;
                    s3x = nsx;
                    s3y = nsy;
                    s3z = nsz;
                }

                vkx = nvx;
                vky = nvy;
                vkz = nvz;
                akx = nax;
                aky = nay;
                akz = naz;
                skx = nsx;
                sky = nsy;
                skz = nsz;
            }

            // Which lanes need the scalar finish: a landing is possible (the cubic's lower bound over the step is not
            // clearly above the plane: min(f0, f1) <= 4/27 (max(-m0, 0) + max(m1, 0)), with a margin), or a number is
            // not finite (x - x is NaN exactly then).
            Vector3d n = Ground.Normal;
            var nx = new Vector<double>(n.X);
            var ny = new Vector<double>(n.Y);
            var nz = new Vector<double>(n.Z);
            Vector3d o = Ground.Point;
            Vector<double> f0 = (px - new Vector<double>(o.X)) * nx + (py - new Vector<double>(o.Y)) * ny + (pz - new Vector<double>(o.Z)) * nz;
            Vector<double> f1 = (npx - new Vector<double>(o.X)) * nx + (npy - new Vector<double>(o.Y)) * ny + (npz - new Vector<double>(o.Z)) * nz;
            Vector<double> m0 = (vx * nx + vy * ny + vz * nz) * h;
            Vector<double> m1 = (nvx * nx + nvy * ny + nvz * nz) * h;
            Vector<double> reach = new Vector<double>(HermiteBound) * (Vector.Max(-m0, Vector<double>.Zero) + Vector.Max(m1, Vector<double>.Zero)) +
                new Vector<double>(1e-9) * (Vector.Abs(f0) + Vector.Abs(f1) + Vector.Abs(m0) + Vector.Abs(m1));
            // Not "min(f0, f1) <= reach": a NaN distance (Plane.SignedDistance's overflow, which the scalar path forms
            // without NaN) must go to the scalar finish too, and a NaN fails every comparison.
            Vector<long> near = ~(Vector.GreaterThan(f0, reach) & Vector.GreaterThan(f1, reach));
            Vector<double> check = (npx - npx) + (npy - npy) + (npz - npz) + (nvx - nvx) + (nvy - nvy) + (nvz - nvz) +
                (nwx - nwx) + (nwy - nwy) + (nwz - nwz) + (nax - nax) + (nay - nay) + (naz - naz) + (nsx - nsx) + (nsy - nsy) + (nsz - nsz);
            Vector<long> bad = ~Vector.Equals(check, Vector<double>.Zero) | perBall;
            Vector<long> special = (near | bad) & active;
            Vector<long> plain = active & ~special;

            var nt = new Vector<double>(_t, start) + h;
            Vector.ConditionalSelect(plain, npx, px).CopyTo(_px, start);
            Vector.ConditionalSelect(plain, npy, py).CopyTo(_py, start);
            Vector.ConditionalSelect(plain, npz, pz).CopyTo(_pz, start);
            Vector.ConditionalSelect(plain, nvx, vx).CopyTo(_vx, start);
            Vector.ConditionalSelect(plain, nvy, vy).CopyTo(_vy, start);
            Vector.ConditionalSelect(plain, nvz, vz).CopyTo(_vz, start);
            Vector.ConditionalSelect(plain, nwx, wx).CopyTo(_wx, start);
            Vector.ConditionalSelect(plain, nwy, wy).CopyTo(_wy, start);
            Vector.ConditionalSelect(plain, nwz, wz).CopyTo(_wz, start);
            Vector.ConditionalSelect(plain, nax, ax).CopyTo(_ax, start);
            Vector.ConditionalSelect(plain, nay, ay).CopyTo(_ay, start);
            Vector.ConditionalSelect(plain, naz, az).CopyTo(_az, start);
            Vector.ConditionalSelect(plain, nsx, sx).CopyTo(_sx, start);
            Vector.ConditionalSelect(plain, nsy, sy).CopyTo(_sy, start);
            Vector.ConditionalSelect(plain, nsz, sz).CopyTo(_sz, start);
            Vector.ConditionalSelect(plain, nt, new Vector<double>(_t, start)).CopyTo(_t, start);

            if (Vector.EqualsAll(special, Vector<long>.Zero))
            {
                for (int lane = 0; lane < _width; lane++)
                {
                    _startsFlight[start + lane] &= plain[lane] == 0;
                }

                return;
            }

            for (int lane = 0; lane < _width; lane++)
            {
                int i = start + lane;
                if (special[lane] == 0)
                {
                    _startsFlight[i] &= plain[lane] == 0;
                    continue;
                }

                if (bad[lane] != 0)
                {
                    // A number the lane formed is not finite, or a stage spin's squares overflowed: the kernel's own step
                    // decides. The lanes' plain |v| and |w| are infinite past about 1.34e154 (m/s, rad/s) where the
                    // kernel's scaled ones are not (there the single-ball step can be finite and taken); everywhere else
                    // the kernel forms the same non-finite step and refuses it. The arrays still hold the lane's start.
                    StepScalar(i, step);
                    continue;
                }

                var s0 = new FlightState(new Vector3d(px[lane], py[lane], pz[lane]), new Vector3d(vx[lane], vy[lane], vz[lane]),
                    new Vector3d(wx[lane], wy[lane], wz[lane]), _t[i]);
                var d0 = new StateDerivative(s0.Velocity, new Vector3d(ax[lane], ay[lane], az[lane]), new Vector3d(sx[lane], sy[lane], sz[lane]));
                var s1 = new FlightState(new Vector3d(npx[lane], npy[lane], npz[lane]), new Vector3d(nvx[lane], nvy[lane], nvz[lane]),
                    new Vector3d(nwx[lane], nwy[lane], nwz[lane]), _t[i] + step);
                var d1 = new StateDerivative(s1.Velocity, new Vector3d(nax[lane], nay[lane], naz[lane]), new Vector3d(nsx[lane], nsy[lane], nsz[lane]));
                Finish(i, s0, d0, s1, d1);
            }
        }

        private void CheckIndex(int index)
        {
            if ((uint)index >= (uint)_count)
            {
                throw new ArgumentOutOfRangeException(nameof(index), index, $"index must be in [0, {_count - 1}]; got {index}.");
            }
        }

        private static void CheckState(in FlightState state) => Require.FiniteState(state, nameof(state));

        // A ball as it was before an Advance call (RunScalarUndoable).
        private struct SavedBall
        {
            public FlightState State;
            public StateDerivative Derivative;
            public bool StartsFlight;
            public long Call; // the call that saved it
        }
    }
}
