using System;
using MagnusBall.Flight;
using MagnusBall;
using MagnusBall.Integration;
using MagnusBall.Stepping;
using UnityEngine;

namespace MagnusBall.Samples.TennisScene.Unity
{
    /// <summary>Which integrator steps the ball (the inspector's drop-down).</summary>
    public enum IntegratorChoice
    {
        /// <summary>Explicit Euler (first order; the thesis's alternative).</summary>
        Euler,

        /// <summary>Semi-implicit Euler (first order; the usual game-engine method).</summary>
        SemiImplicitEuler,

        /// <summary>Heun / RK2 (second order).</summary>
        Heun,

        /// <summary>Classic RK4 (fourth order; the thesis's default).</summary>
        RungeKutta4,

        /// <summary>RK4 with stability-safe substeps (StableIntegrator): for large fixed steps with light, fast balls.</summary>
        StableRungeKutta4,
    }

    /// <summary>The court surface the ball bounces on (the inspector's drop-down).</summary>
    public enum CourtSurface
    {
        /// <summary>No bounce: the flight ends where the ball first touches the court.</summary>
        None,

        /// <summary>Hard court (Cross 2020 values).</summary>
        Hard,

        /// <summary>Clay.</summary>
        Clay,

        /// <summary>Grass.</summary>
        Grass,
    }

    /// <summary>How the launch spin is entered in the inspector.</summary>
    public enum SpinInput
    {
        /// <summary>By effect: topspin (negative: backspin) and sidespin in rpm, built with Spin.Topspin / Spin.Toward.</summary>
        ByEffect,

        /// <summary>As rad/s components about Unity's x, y, z axes, left-hand rule (the thesis's start screen).</summary>
        Components,
    }

    /// <summary>
    /// The tennis ball. Its flight is computed by MagnusBall (gravity, drag, Magnus) in fixed steps through a
    /// <see cref="FixedStepDriver"/>, fed from <c>Update</c> with <c>Time.deltaTime</c> (or from
    /// <c>FixedUpdate</c>), and the transform is set to the interpolated render state. No Rigidbody: Unity clips
    /// a Rigidbody's angular velocity at <c>maxAngularVelocity</c> (7 rad/s by default before 2022, 50 rad/s
    /// after), far below a tennis ball's 100-400 rad/s, so the spin lives in the library's state only.
    /// </summary>
    /// <remarks>
    /// World axes are the thesis's scene: +x into the screen (down the court), +y up, +z to the left (see
    /// <see cref="TennisCourt"/>). The library works in these coordinates unchanged (<see cref="UnityFrame"/>).
    /// Space launches, R puts the ball back at the serving position.
    /// </remarks>
    public class TennisBall : MonoBehaviour
    {
        [Header("Initial velocity, m/s (thesis start screen: front = +x, top = +y, left = +z)")]
        // Defaults: the headless runner's flat serve (50 m/s, -5.3 deg, 9 deg to the left, 800 rpm topspin).
        public float front = 49.17f;
        public float top = -4.62f;
        public float left = 7.79f;

        [Header("Initial spin")]
        [Tooltip("ByEffect: topspin/sidespin in rpm, right in any handedness. Components: rad/s about Unity's axes, left-hand rule.")]
        public SpinInput spinInput = SpinInput.ByEffect;
        [Tooltip("Topspin, rev/min; negative for backspin (slice).")]
        public float topspinRpm = 800f;
        [Tooltip("Sidespin, rev/min; positive curls the ball to the left (+z).")]
        public float sidespinRpm = 0f;
        [Tooltip("Angular velocity, rad/s, about Unity's x, y, z axes (left-hand rule), used when spinInput = Components.")]
        public Vector3 spinComponents = new Vector3(0f, 0f, 0f);

        [Header("Ball and air")]
        [Tooltip("Use Stepanek's spin-dependent coefficients instead of the constants below.")]
        public bool useStepanekCoefficients = true;
        [Tooltip("C_M, the Magnus (lift) coefficient (thesis: 0.175).")]
        public float magnusCoefficient = 0.175f;
        [Tooltip("C_D, the drag coefficient (thesis: 0.55).")]
        public float dragCoefficient = 0.55f;
        [Tooltip("kg")]
        public float mass = 0.057f;
        [Tooltip("m")]
        public float radius = 0.033f;
        [Tooltip("kg/m^3 (thesis: 1.29, 'pure air'; Cross 2011: 1.21)")]
        public float airDensity = 1.21f;
        [Tooltip("The court the ball bounces on (Cross's slide/grip bounce), or None to stop at the first landing.")]
        public CourtSurface surface = CourtSurface.Hard;

        [Header("Stepping")]
        public IntegratorChoice integrator = IntegratorChoice.RungeKutta4;
        [Tooltip("Fixed step, s. The flight is the same at any frame rate for a given step.")]
        public float fixedStep = 1f / 240f;
        [Tooltip("Frame-time clamp, s: a longer frame (a hitch) is cut to this.")]
        public float maxFrameDelta = 0.25f;
        [Tooltip("Step from FixedUpdate with Time.fixedDeltaTime instead of from Update with Time.deltaTime.")]
        public bool stepInFixedUpdate = false;

        [Header("Launch")]
        [Tooltip("Where the ball is served from, m: behind the near baseline, 2.87 m up (the thesis's serving height).")]
        public Vector3 servePosition = new Vector3(-11.985f, 2.87f, -0.8f);
        public bool launchOnStart = true;
        public KeyCode launchKey = KeyCode.Space;
        public KeyCode resetKey = KeyCode.R;

        private readonly FlightEvent[] _events = new FlightEvent[8];
        private SceneSettings _settings;
        private ShotSimulation _simulation;
        private FixedStepDriver _driver;
        private bool _flying;

        /// <summary>The driver of the current flight (null before the first launch).</summary>
        public FixedStepDriver Driver => _driver;

        /// <summary>The scene settings built from the inspector at the last launch.</summary>
        public SceneSettings Settings => _settings;

        /// <summary>True while the ball is in the air.</summary>
        public bool IsFlying => _flying;

        /// <summary>Raised at every touch of the court: each bounce (or, with no surface, the landing that ends the flight).</summary>
        public event Action<FlightEvent> Touched;

        private void Start()
        {
            ResetBall();
            if (launchOnStart)
            {
                Launch();
            }
        }

        private void Update()
        {
            if (Input.GetKeyDown(launchKey))
            {
                Launch();
            }

            if (Input.GetKeyDown(resetKey))
            {
                ResetBall();
            }

            if (_driver == null)
            {
                return;
            }

            if (!stepInFixedUpdate && _flying)
            {
                // Frame time in, fixed steps out: the flight does not depend on the frame rate.
                Step(Time.deltaTime);
            }

            // Update mode: draw the state interpolated between the last two fixed steps (alpha = accumulator / step).
            // FixedUpdate mode: draw the latest fixed state, the one Unity's own FixedUpdate physics sees (no
            // interpolation: the ball moves in FixedUpdate-sized hops, as a non-interpolated Rigidbody does).
            FlightState render = stepInFixedUpdate ? _driver.State : _driver.RenderState;
            transform.position = UnityFrame.ToUnity(render.Position);
            ShowSpin(render.AngularVelocity, Time.deltaTime);
        }

        private void FixedUpdate()
        {
            if (stepInFixedUpdate && _flying && _driver != null)
            {
                // With fixedStep equal to Time.fixedDeltaTime this is exactly one library step per FixedUpdate.
                Step(Time.fixedDeltaTime);
            }
        }

        /// <summary>Builds the model from the inspector and launches the ball from the serving position.</summary>
        public void Launch()
        {
            _settings = new SceneSettings(
                mass, radius, airDensity, useStepanekCoefficients, dragCoefficient, magnusCoefficient,
                IntegratorName(integrator), fixedStep, surface.ToString().ToLowerInvariant());
            _simulation = new ShotSimulation(_settings);
            _driver = _simulation.CreateDriver(LaunchState(), maxFrameDelta);
            _flying = true;
        }

        /// <summary>The launch state from the inspector fields, in Unity's (= the library's) coordinates.</summary>
        public FlightState LaunchState()
        {
            Vector3d velocity = new Vector3d(front, top, left);
            Vector3d spin = spinInput == SpinInput.Components
                ? UnityFrame.ToLibrary(spinComponents) // Unity's left-hand-rule components, used as they are
                : TennisShot.SpinFor(velocity, topspinRpm, sidespinRpm);
            return new FlightState(UnityFrame.ToLibrary(servePosition), velocity, spin);
        }

        /// <summary>Puts the ball back at the serving position, not flying.</summary>
        public void ResetBall()
        {
            _flying = false;
            _driver = null;
            transform.position = servePosition;
            transform.rotation = Quaternion.identity;
        }

        private void Step(float frameDelta)
        {
            AdvanceResult result = _driver.Advance(frameDelta, _events);
            for (int i = 0; i < result.EventCount; i++)
            {
                FlightEvent e = _events[i];
                switch (e.Kind)
                {
                    case FlightEventKinds.PlaneCrossing:
                        Debug.Log($"net: the ball passes {_simulation.NetClearance(e.Position):F2} m above the cord at t = {e.Time:F3} s");
                        break;
                    case FlightEventKinds.Bounce:
                        Debug.Log($"bounce at x = {e.Position.X:F2} m, z = {e.Position.Z:F2} m, t = {e.Time:F3} s: " +
                                  $"{e.State.Velocity.Length:F1} m/s in, {e.After.Velocity.Length:F1} m/s out ({e.Regime})" +
                                  (e.StartsRolling ? ", now rolling" : string.Empty));
                        Touched?.Invoke(e);
                        break;
                    case FlightEventKinds.Landing:
                        Debug.Log($"lands at x = {e.Position.X:F2} m, z = {e.Position.Z:F2} m, t = {e.Time:F3} s (no bounce model)");
                        Touched?.Invoke(e);
                        break;
                    case FlightEventKinds.Rest:
                        Debug.Log($"stops at x = {e.Position.X:F2} m, z = {e.Position.Z:F2} m, t = {e.Time:F3} s");
                        break;
                }
            }

            _flying = !_driver.IsFinished;
        }

        private void ShowSpin(Vector3d angularVelocity, float frameDelta)
        {
            // Spin the mesh for the eye. Unity rotates by the left-hand rule, the same convention the spin is
            // expressed in, so the axis goes in unchanged.
            double rate = angularVelocity.Length;
            if (!_flying || rate <= 0)
            {
                return;
            }

            float degrees = (float)(rate * frameDelta * (180.0 / Math.PI));
            Vector3 axis = UnityFrame.ToUnity(angularVelocity / rate);
            transform.rotation = Quaternion.AngleAxis(degrees, axis) * transform.rotation;
        }

        private static string IntegratorName(IntegratorChoice choice)
        {
            switch (choice)
            {
                case IntegratorChoice.Euler: return ExplicitEuler.Instance.Name;
                case IntegratorChoice.SemiImplicitEuler: return SemiImplicitEuler.Instance.Name;
                case IntegratorChoice.Heun: return Heun.Instance.Name;
                case IntegratorChoice.StableRungeKutta4: return StableIntegrator.RungeKutta4.Name;
                default: return RungeKutta4.Instance.Name;
            }
        }
    }
}
