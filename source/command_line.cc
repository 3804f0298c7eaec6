#include <deal.II/base/exceptions.h>

#include <thinlayer/command_line.h>
#include <thinlayer/input_error.h>
#include <thinlayer/parameters.h>
#include <thinlayer/run.h>
#include <thinlayer/sweep.h>

namespace thinlayer
{
  namespace
  {
    void
    print_usage(std::ostream &out)
    {
      out << "usage: thinlayer FILE.prm [-s \"Section/Entry=value\"]...\n"
          << "       thinlayer --print-parameters\n"
          << "       thinlayer --help\n\n"
          << "Runs the scene described by FILE.prm (a gmsh .geo or .msh plus\n"
          << "materials, boundary conditions and a load programme). -s\n"
          << "overrides any entry, e.g. -s \"Mesh/Geometry "
             "parameters=alpha=30\"\n"
          << "or -s \"Material 2/Young's modulus=1e4\". Results go to the\n"
          << "directory named by Output/Directory: history.csv, summary.json,\n"
          << "fields.pvd with one VTU per load step.\n";
    }
  } // namespace


  int
  run_command_line(const std::vector<std::string> &arguments,
                   std::ostream                   &out,
                   std::ostream                   &err)
  {
    std::string              file;
    std::vector<std::string> overrides;
    for (unsigned int i = 0; i < arguments.size(); ++i)
      {
        const std::string &a = arguments[i];
        if (a == "--help" || a == "-h")
          {
            print_usage(out);
            return 0;
          }
        else if (a == "--print-parameters")
          {
            ParameterReader().print_parameters(out);
            return 0;
          }
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
    if (file.empty())
      {
        print_usage(err);
        return 2;
      }

    try
      {
        const Parameters parameters = ParameterReader().read(file, overrides);
        if (parameters.sweep.values.empty())
          run_scene(parameters, out);
        else
          run_sweep(file, overrides, parameters, out);
        return 0;
      }
    catch (const InputError &e)
      {
        err << "thinlayer: " << e.what() << '\n';
        return 1;
      }
    catch (const ExceptionBase &e)
      {
        err << "thinlayer: internal error: ";
        e.print_info(err);
        err << '\n';
        return 3;
      }
    catch (const std::exception &e)
      {
        err << "thinlayer: internal error: " << e.what() << '\n';
        return 3;
      }
  }
} // namespace thinlayer
