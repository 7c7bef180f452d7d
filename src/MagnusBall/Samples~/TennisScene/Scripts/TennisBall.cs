using System;
using MagnusBall.Components;
using MagnusBall.Contact.Swings;
using MagnusBall.Flight;
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

    /// <summary>What the inspector sets: the racket swing that hits the ball (the default), or the launch itself.</summary>
    public enum LaunchInput
    {
        /// <summary>The swing: racket speed, path, face tilt and turn, azimuth, impact point; the launch is what the library's impact law makes of it.</summary>
        Swing,

        /// <summary>The launch velocity and spin directly (the thesis's start screen).</summary>
        Launch,
    }

    /// <summary>Where on the strings the ball is hit, through the apparent COR measured there (RacketSwing's constants).</summary>
    public enum StringBedPoint
    {
        /// <summary>The centre of the strings: ACOR 0.45.</summary>
        Centre,

        /// <summary>Near the tip: ACOR 0.10.</summary>
        Tip,

        /// <summary>Near the throat: ACOR 0.50.</summary>
        Throat,
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
    /// By default the inspector sets the racket swing (<see cref="LaunchInput.Swing"/>): the ball, arriving with the
    /// incoming velocity and topspin (at rest for a serve's toss), is hit at the serving position by a
    /// <see cref="RacketSwing"/> built from the swing fields, and the launch is the library's impact law's result
    /// (logged next to the swing). The defaults are the scene's flat serve (<see cref="StandardSwings.FlatServe"/>).
    /// </remarks>
    [RequireComponent(typeof(MagnusBallFlight))]
    public class TennisBall : MonoBehaviour
    {
        [Header("What the inspector sets")]
        [Tooltip("Swing: the racket swing below hits the ball and the library's impact law gives the launch. Launch: the launch velocity and spin below.")]
        public LaunchInput launchBy = LaunchInput.Swing;

        [Header("Swing (the racket at impact; angles in the court frame: up +y, forward +x)")]
        // Defaults: the scene's flat serve made by a swing (StandardSwings.FlatServe).
        [Tooltip("Racket speed at the impact point, m/s.")]
        [Range(1f, 60f)]
        public float racketSpeed = 34f;
        [Tooltip("The racket head's path above the horizontal, degrees (+ low to high: topspin).")]
        [Range(-80f, 80f)]
        public float pathElevation = 0f;
        [Tooltip("The face normal's tilt above the horizontal, degrees (+ open: slice; - closed).")]
        [Range(-80f, 80f)]
        public float faceTilt = -6.845f;
        [Tooltip("The face normal's turn from the path, degrees, + toward the hitter's right (-z): sidespin.")]
        [Range(-60f, 60f)]
        public float faceTurn = 0f;
        [Tooltip("The path's azimuth from +x, degrees, + toward the hitter's right (-z).")]
        [Range(-90f, 90f)]
        public float swingAzimuth = -9f;
        [Tooltip("Where on the strings the ball is hit (the apparent COR there: centre 0.45, tip 0.10, throat 0.50).")]
        public StringBedPoint impactPoint = StringBedPoint.Centre;
        [Tooltip("The ball's velocity just before the hit, m/s (zero: a serve's toss at its apex; a rally ball: about (-14, -1, 0)).")]
        public Vector3 incomingVelocity = Vector3.zero;
        [Tooltip("The incoming ball's topspin, rev/min (negative: backspin); ignored when it is at rest.")]
        public float incomingTopspinRpm = 0f;

        [Header("Launch, used when launchBy = Launch (thesis start screen: front = +x, top = +y, left = +z), m/s")]
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
        [Min(0.0001f)]
        public float mass = 0.057f;
        [Tooltip("m")]
        [Min(0.0001f)]
        public float radius = 0.033f;
        [Tooltip("kg/m^3 (thesis: 1.29, 'pure air'; Cross 2011: 1.21)")]
        [Min(0f)]
        public float airDensity = 1.21f;
        [Tooltip("The court the ball bounces on (Cross's slide/grip bounce), or None to stop at the first landing.")]
        public CourtSurface surface = CourtSurface.Hard;

        [Header("Stepping")]
        public IntegratorChoice integrator = IntegratorChoice.RungeKutta4;
        [Tooltip("Fixed step, s. The flight is the same at any frame rate for a given step.")]
        [Min(0.0001f)]
        public float fixedStep = 1f / 240f;
        [Tooltip("Frame-time clamp, s: a longer frame (a hitch) is cut to this.")]
        [Min(0.001f)]
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

        /// <summary>The launch the swing gave at the last launch by swing (default before the first one, or when launching by launch).</summary>
        public SwingLaunch LastSwingLaunch { get; private set; }

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

        /// <summary>
        /// Builds the scene's model from the inspector, hands it to the flight component and launches the ball from the
        /// serving position: hit by the inspector's swing (the default), or with the inspector's launch.
        /// </summary>
        /// <returns>False when the swing misses the ball (the ball was not moving into the racket face); nothing is launched then.</returns>
        /// <exception cref="ArgumentException">An inspector value is outside its range (the message names it); nothing changes.</exception>
        public bool Launch()
        {
            var settings = new SceneSettings(
                mass, radius, airDensity, useStepanekCoefficients, dragCoefficient, magnusCoefficient,
                IntegratorName(integrator), fixedStep, surface.ToString().ToLowerInvariant());
            FlightState start;
            SwingLaunch swingLaunch = default;
            if (launchBy == LaunchInput.Swing)
            {
                TennisSwing swing = Swing();
                swingLaunch = swing.Launch(settings.Ball);
                if (!swingLaunch.IsHit)
                {
                    Debug.Log($"the racket misses the ball ({swing.Swing}): the ball is not moving into its face. Nothing launched.");
                    return false;
                }

                start = new FlightState(swing.Start, swingLaunch.Velocity, swingLaunch.AngularVelocity);
                Debug.Log($"swing: {swing.Describe()} -> launch {swingLaunch.Speed:F1} m/s, elevation {swingLaunch.ElevationDegrees:F1} deg, " +
                          $"topspin {Spin.ToRpm(swingLaunch.LaunchSpin.Topspin):F0} rpm, sidespin {Spin.ToRpm(swingLaunch.LaunchSpin.Sidespin):F0} rpm ({swingLaunch.Impact.Regime})");
            }
            else
            {
                start = LaunchState();
            }

            // Configure and launch in one call, all or nothing: a refused start (a launch field not finite) leaves the
            // flight, its configuration and this component's settings as they were.
            var simulation = new ShotSimulation(settings);
            MagnusBallFlight flight = Flight;
            flight.Launch(start, settings.Model, settings.Integrator, settings.FixedStep, simulation.Events, settings.Bounce, maxFrameDelta);
            flight.stepIn = stepInFixedUpdate ? StepIn.FixedUpdate : StepIn.Update;
            _settings = settings;
            _simulation = simulation;
            LastSwingLaunch = swingLaunch;
            return true;
        }

        /// <summary>
        /// The swing from the inspector's swing fields: a <see cref="RacketSwing"/> meeting the ball at the serving
        /// position, the ball arriving with the incoming velocity and topspin.
        /// </summary>
        /// <exception cref="ArgumentException">A swing field is outside its range or not finite; the message names it.</exception>
        public TennisSwing Swing()
        {
            double acor = impactPoint == StringBedPoint.Tip ? RacketSwing.TipRestitution
                : impactPoint == StringBedPoint.Throat ? RacketSwing.ThroatRestitution
                : RacketSwing.CentreRestitution;
            var racket = new RacketSwing(racketSpeed, pathElevation, faceTilt, acor, swingAzimuth, faceTurn);
            return new TennisSwing(
                "inspector swing", UnityFrame.ToLibrary(servePosition), UnityFrame.ToLibrary(incomingVelocity), incomingTopspinRpm,
                racket, TargetArea.FarDeuceServiceBox);
        }

        /// <summary>The launch state from the inspector's launch fields (used when launchBy = Launch), in Unity's (= the library's) coordinates.</summary>
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
