// BallBatch: many balls stepped together (the public surface, the scalar lanes ball by ball and each ball's landing).
// The vector lanes, four balls in one SIMD step, are in BallBatch.Vector.cs.
using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using MagnusBall.Aerodynamics;
using MagnusBall.Flight;
using MagnusBall.Integration;

using MagnusBall.Integration.Kernels;

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
    public sealed partial class BallBatch
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
            if (FlightKernel.Of(model).RunsUserCode)
            {
                _saved = new SavedBall[length];
            }
        }

        /// <summary>The flight model.</summary>
        internal FlightModel Model { get; }

        /// <summary>The plane the balls land on.</summary>
        internal Plane Ground { get; }

        /// <summary>The most balls the batch holds.</summary>
        internal int Capacity { get; }

        /// <summary>The balls in the batch.</summary>
        public int Count => _count;

        /// <summary>
        /// True when the batch steps <see cref="Vector{T}.Count"/> balls at a time (the hardware accelerates
        /// <see cref="Vector{T}"/> and the model's laws have vector forms); false when it steps ball by ball. The results
        /// are the same either way.
        /// </summary>
        internal bool IsVectorized { get; }

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
            StateDerivative derivative = FlightKernel.DerivativeOf(Model, state);
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
            FlightState end = FlightKernel.Of(Model).RungeKutta4(start, k1, step, out StateDerivative k);
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
                FlightState end = FlightKernel.Of(Model).RungeKutta4(state, k1, step, out StateDerivative k);
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
