using System;
using MagnusBall.Flight;
using MagnusBall.Components;
using MagnusBall.Stepping;
using UnityEngine;

namespace MagnusBall.Samples.TennisScene.Scripts
{
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
    /// The tennis ball: the scene's settings (ball, air, coefficients, court, integrator, fixed step, from the
    /// inspector) handed to the package's <see cref="MagnusBallFlight"/> component, which flies the transform
    /// through a <see cref="FixedStepDriver"/> from <c>Update</c> (or <c>FixedUpdate</c>) and raises the
    /// events this script logs. No Rigidbody: the spin lives in the library's state (see MagnusBallFlight).
    /// </summary>
    /// <remarks>
    /// World axes are the thesis's scene: +x into the screen (down the court), +y up, +z to the left (see
    /// <see cref="TennisCourt"/>). The library works in these coordinates unchanged (<see cref="UnityFrame"/>).
    /// Space launches, R puts the ball back at the serving position (keys through <see cref="SceneInput"/>).
    /// </remarks>
    [RequireComponent(typeof(MagnusBallFlight))]
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

        private SceneSettings _settings;
        private ShotSimulation _simulation;
        private MagnusBallFlight _flight;

        /// <summary>The flight component that flies this ball.</summary>
        public MagnusBallFlight Flight
        {
            get
            {
                if (_flight == null)
                {
                    // Unity adds it for the RequireComponent; added here too when the script is created in code.
                    _flight = GetComponent<MagnusBallFlight>();
                    if (_flight == null)
                    {
                        _flight = gameObject.AddComponent<MagnusBallFlight>();
                    }

                    _flight.Landed += OnLanding;
                    _flight.Bounced += OnBounce;
                    _flight.PlaneCrossed += OnNet;
                    _flight.Stopped += OnStop;
                }

                return _flight;
            }
        }

        /// <summary>The driver of the current flight (null before the first launch).</summary>
        public FixedStepDriver Driver => Flight.Driver;

        /// <summary>The shot simulation of the last launch (the scene's events: the court and the net).</summary>
        public ShotSimulation Simulation => _simulation;

        /// <summary>The scene settings built from the inspector at the last launch.</summary>
        public SceneSettings Settings => _settings;

        /// <summary>True while the ball is in the air.</summary>
        public bool IsFlying => Flight.IsFlying;

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
            if (SceneInput.WasPressed(launchKey))
            {
                Launch();
            }

            if (SceneInput.WasPressed(resetKey))
            {
                ResetBall();
            }
        }

        /// <summary>Builds the scene's model from the inspector, hands it to the flight component and launches the ball from the serving position.</summary>
        public void Launch()
        {
            _settings = new SceneSettings(
                mass, radius, airDensity, useStepanekCoefficients, dragCoefficient, magnusCoefficient,
                IntegratorName(integrator), fixedStep, surface.ToString().ToLowerInvariant());
            _simulation = new ShotSimulation(_settings);
            MagnusBallFlight flight = Flight;
            flight.stepIn = stepInFixedUpdate ? StepIn.FixedUpdate : StepIn.Update;
            flight.Configure(_settings.Model, _settings.Integrator, _settings.FixedStep, _simulation.Events, _settings.Bounce, maxFrameDelta);
            flight.Launch(LaunchState());
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
            Flight.Cancel();
            transform.position = servePosition;
            transform.rotation = Quaternion.identity;
        }

        private void OnNet(FlightEvent e) =>
            Debug.Log($"net: the ball passes {_simulation.NetClearance(e.Position):F2} m above the cord at t = {e.Time:F3} s");

        private void OnBounce(FlightEvent e)
        {
            Debug.Log($"bounce at x = {e.Position.X:F2} m, z = {e.Position.Z:F2} m, t = {e.Time:F3} s: " +
                      $"{e.State.Velocity.Length:F1} m/s in, {e.After.Velocity.Length:F1} m/s out ({e.Regime})" +
                      (e.StartsRolling ? ", now rolling" : string.Empty));
            Touched?.Invoke(e);
        }

        private void OnLanding(FlightEvent e)
        {
            Debug.Log($"lands at x = {e.Position.X:F2} m, z = {e.Position.Z:F2} m, t = {e.Time:F3} s (no bounce model)");
            Touched?.Invoke(e);
        }

        private void OnStop(FlightEvent e) =>
            Debug.Log($"stops at x = {e.Position.X:F2} m, z = {e.Position.Z:F2} m, t = {e.Time:F3} s");

        private static string IntegratorName(IntegratorChoice choice) => FlightSettings.Integrator(choice).Name;
    }
}
