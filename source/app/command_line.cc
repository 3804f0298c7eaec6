#include <deal.II/base/exceptions.h>

#include <thinlayer/app/adaptive_run.h>
#include <thinlayer/app/command_line.h>
#include <thinlayer/app/run.h>
#include <thinlayer/app/sweep.h>
#include <thinlayer/base/input_error.h>
#include <thinlayer/base/interruption.h>
#include <thinlayer/output/reference_check.h>
#include <thinlayer/output/results_directory.h>
#include <thinlayer/parallel/mpi.h>
#include <thinlayer/parameters/parameter_reader.h>
#include <thinlayer/parameters/parameter_text.h>
#include <thinlayer/parameters/parameters.h>
#include <thinlayer/solvers/linear_solver_failure.h>

#include <csignal>
#include <sstream>

namespace thinlayer
{
  namespace
  {
    void
    print_usage(std::ostream &out)
    {
      out
        << "usage: thinlayer FILE.prm [-s \"Section/Entry=value\"]...\n"
        << "       thinlayer [FILE.prm [-s ...]] --print-parameters\n"
        << "       thinlayer --help\n\n"
        << "Runs the scene described by FILE.prm (a gmsh .geo or .msh plus\n"
        << "materials, boundary conditions and a load programme). -s\n"
        << "overrides any entry, e.g. -s \"Mesh/Geometry "
           "parameters=alpha=30\"\n"
        << "or -s \"Material 2/Young's modulus=1e4\". Results go to the\n"
        << "directory named by Output/Directory: history.csv, summary.json,\n"
        << "fields.pvd with one VTU per load step. --print-parameters\n"
        << "prints every entry with its documentation: with FILE.prm, that\n"
        << "scene's values (a file that runs as given), else the defaults.\n\n"
        << "Exit status: 0 a result (non-convergence is one), 1 bad input,\n"
        << "a failed write or a sweep run that ended in an error, 2 a bad\n"
        << "command line or environment, 3 an internal error or a failed\n"
        << "linear solver\n"
        << "(out of memory, CG not converging), 4 a run that missed its\n"
        << "Reference/Expected outcome or load range, 128 + N signal N.\n";
    }


    /**
     * The parameter file and the overrides of @p arguments. Returns the
     * exit status where the command line is done (help, the parameter
     * list, or a bad command line: 2), or -1 to go on with the run.
     */
    int
    parse_arguments(const std::vector<std::string> &arguments,
                    std::string                    &file,
                    std::vector<std::string>       &overrides,
                    bool                           &print,
                    std::ostream                   &out,
                    std::ostream                   &err)
    {
      for (unsigned int i = 0; i < arguments.size(); ++i)
        {
          const std::string &a = arguments[i];
          if (a == "--help" || a == "-h")
            {
              print_usage(out);
              return 0;
            }
          else if (a == "--print-parameters")
            print = true;
          else if (a == "-s" || a == "--set")
            {
              if (i + 1 == arguments.size())
                {
                  err << "thinlayer: " << a
                      << " needs an argument \"Section/Entry=value\"\n";
                  return 2;
                }
              overrides.push_back(arguments[++i]);
            }
          else if (!a.empty() && a[0] == '-')
            {
              err << "thinlayer: unknown option '" << a << "'\n";
              print_usage(err);
              return 2;
            }
          else if (file.empty())
            file = a;
          else
            {
              err << "thinlayer: only one parameter file, got '" << file
                  << "' and '" << a << "'\n";
              return 2;
            }
        }
      if (print && file.empty() && !overrides.empty())
        {
          err << "thinlayer: -s needs a parameter file to override\n";
          return 2;
        }
      if (print && file.empty())
        {
          ParameterReader().print_parameters(out);
          return 0;
        }
      if (file.empty())
        {
          print_usage(err);
          return 2;
        }
      return -1;
    }
  } // namespace


  int
  run_command_line(const std::vector<std::string> &arguments,
                   std::ostream                   &out,
                   std::ostream                   &err)
  {
    // Every rank reads the same command line and parameter file and meets
    // the same errors in them; rank 0 reports those. An error that only
    // one rank can meet (a failed write, an internal error) is reported by
    // that rank, which then ends all of them.
    std::ostringstream quiet;
    std::ostream      &root_err = mpi::is_root() ? err : quiet;
    const std::string  rank =
      mpi::n_ranks() > 1 ? "rank " + std::to_string(mpi::rank()) + ": " : "";

    std::string              file;
    std::vector<std::string> overrides;
    bool                     print = false;
    if (const int status =
          parse_arguments(arguments, file, overrides, print, out, root_err);
        status >= 0)
      return status;

    try
      {
        const ScopedInterruption interruption;
        // A file size limit (ulimit -f) then fails the write (EFBIG), which
        // is reported like a full disk, instead of killing the program.
        std::signal(SIGXFSZ, SIG_IGN);
        // The scene's every entry, documented: a file that runs as given.
        if (print)
          {
            ParameterReader().read(file, overrides, &out);
            return 0;
          }
        const Parameters parameters = ParameterReader().read(file, overrides);
        SweepResult      result;
        if (parameters.sweep.values.empty())
          {
            const RunSummary summary = parameters.adaptivity.active()
                                         ? run_adaptive(parameters, out)
                                         : run_scene(parameters, out);
            result.missed_references =
              check_reference(parameters.reference, summary).passed ? 0 : 1;
          }
        else
          result = run_sweep(file, overrides, parameters, out);
        out.flush();
        // 128 + the signal, as a shell reports a process it ended. A signal
        // first: mpirun, sent SIGTERM, passes it on and stops forwarding
        // standard output, so that the ranks' last lines fail.
        if (interrupted())
          return 128 + interruption_signal();
        if (!out)
          {
            root_err
              << "thinlayer: cannot write to standard output; the results "
                 "are in Output/Directory\n";
            return 1;
          }
        if (result.failed_runs > 0)
          {
            root_err << "thinlayer: " << result.failed_runs
                     << " run(s) of the sweep ended in an error (sweep.csv, "
                        "column error)\n";
            return 1;
          }
        if (result.missed_references > 0)
          {
            root_err << "thinlayer: " << result.missed_references
                     << " run(s) missed what Reference/Expected outcome or "
                        "Expected load range asks of them (the line 'reference "
                        "check FAILED' says what)\n";
            return 4;
          }
        return 0;
      }
    // Messages may quote the input, which may be binary: control bytes
    // are written as \xNN.
    catch (const InputError &e)
      {
        root_err << "thinlayer: " << printable(e.what()) << '\n';
        return 1;
      }
    catch (const Interrupted &e)
      {
        root_err << "thinlayer: " << printable(e.what()) << '\n';
        return 128 + interruption_signal();
      }
    catch (const WriteError &e)
      {
        err << "thinlayer: " << rank << printable(e.what())
            << "; Output/Directory still holds the run it held before\n";
        mpi::abort_all(1);
        return 1;
      }
    catch (const LinearSolverFailure &e)
      {
        err << "thinlayer: " << rank
            << "the linear solver failed: " << printable(e.what()) << '\n';
        mpi::abort_all(3);
        return 3;
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        err << "thinlayer: " << rank
            << "internal error: " << printable(info.str()) << '\n';
        mpi::abort_all(3);
        return 3;
      }
    catch (const std::exception &e)
      {
        err << "thinlayer: " << rank
            << "internal error: " << printable(e.what()) << '\n';
        mpi::abort_all(3);
        return 3;
      }
  }
} // namespace thinlayer
